// SPDX-License-Identifier: MIT
// Practice that never runs out: for every topic an endless series of exercises, each a small random scene drawn
// from a seed, run through the very machine the lessons animate, and a question whose answer is one of that run's
// events. A teacher hands out "series 1234"; every student, the window and `hsrviz practice` see the same exercises.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene.h"
#include "state/practice/wording.h"

namespace hsr::viz::practice {

enum class Level : std::uint8_t { easy = 1, medium = 2, hard = 3 };  // hard: close to degenerate, never on it

struct Exercise {
    std::string topic;
    std::uint64_t series = 0;
    std::uint64_t index = 0;            // exercise `index` of the series
    Level level = Level::easy;
    std::string question;               // in English, as `hsrviz practice` prints it: `asked`'s English
    std::vector<std::string> choices;   // the answer is one of them (the English of `offered`); empty when the
                                        // answer is a number
    Wording asked;                      // the question in words any language can say (ask())
    std::vector<Wording> offered;       // the choices likewise (offer())
    std::string answer;                 // a choice, or the number as the machine computed it ("0.25")
    double tolerance = 0;               // how far a typed number may be from the answer and still be right
    std::string deciding;               // the sentence of the machine's event that decides the answer
    std::size_t deciding_step = 0;      // that event's step in the run
    std::optional<std::size_t> hold_at; // where the window holds before the answer, when an earlier event gives it
                                        // away (Liang–Barsky's q/p before t_enter moves); else deciding_step
    nlohmann::json given;               // the question's data (points, planes, …) as numbers, for answer sheets and tests
    algo::Scene scene;                  // what the window plays, with `algorithm` (a registry id): the deciding
    std::string algorithm;              // event is its step `deciding_step`
    int columns = 0;                    // floating-horizon exercises: the screen's columns (the lesson's grid width);
                                        // 0: a lesson's default
    std::string cull;                   // culling exercises: the pipeline's stages, as a lesson's `cull` names them
                                        // (empty: a lesson's default, every stage)

    void ask(Wording w);
    // The choices, and the right one among them.
    void offer(std::vector<Wording> choices, std::size_t right);
    // The choice written as `english` says in words (a reply given, the answer); nothing when it is no choice.
    const Wording* choice(std::string_view english) const;
};

// A topic's exercise maker: the exercise for one seed, or nothing when the scene drawn was degenerate or the question
// it asks is unanswerable (the series then draws again, a bounded number of times).
struct Draw {
    std::uint64_t seed;
    Level level;
};
using MakeExercise = std::function<std::optional<Exercise>(Draw)>;

struct Topic {
    std::string_view id;      // as `hsrviz practice` names it
    std::string_view title;
    std::vector<std::string_view> algorithms;  // whose lessons practise this topic (registry ids)
    MakeExercise make;
    // the templates its questions and choices use ([exercise] in a catalogue): its own, and those it shares
    std::vector<std::span<const algo::Saying>> sayings;
};

// Every topic's templates, each once: what the catalogues' [exercise] sections translate.
std::vector<algo::Saying> practice_sayings();

std::span<const Topic> topics();
const Topic* find_topic(std::string_view id);

// Exercise `index` of series `series`. Throws std::runtime_error if every redraw was degenerate (a bug: the makers
// reject rarely).
Exercise exercise(const Topic& topic, std::uint64_t series, std::uint64_t index, Level level);

// Is this reply right? A choice must be given as written (or by its number, 1 …); a number within the tolerance.
bool grade(const Exercise& e, std::string_view reply);

// A number as an answer: at most `digits` decimals, no trailing zeros ("0.4839", "0.8", "-3").
std::string decimal_text(double v, int digits);
std::string number_text(double v);  // %g: six significant digits, as a question prints its scene's numbers

// The lesson file the window plays an exercise from: its algorithm, its stages, and its scene saved as `scene_file`
// (a name beside the lesson file); its title in English, or in each language of `titles` (language → title).
std::string lesson_toml(const Exercise& e, std::string_view scene_file, const std::map<std::string, std::string>& titles = {});

// One line of `hsrviz practice`'s JSON Lines.
nlohmann::ordered_json to_json(const Exercise& e);

// Each family's topics, in their own files (clip_practice.cpp, backface_practice.cpp, …).
std::vector<Topic> clipping_topics();
std::vector<Topic> backface_topics();
std::vector<Topic> bsp_topics();
std::vector<Topic> zbuffer_topics();
std::vector<Topic> raycast_topics();
std::vector<Topic> culling_topics();
std::vector<Topic> depth_sort_topics();
std::vector<Topic> precision_topics();
std::vector<Topic> scanline_topics();
std::vector<Topic> hiz_topics();
std::vector<Topic> portal_topics();
std::vector<Topic> horizon_topics();
std::vector<Topic> compositing_topics();
std::vector<Topic> perspective_topics();

}  // namespace hsr::viz::practice
