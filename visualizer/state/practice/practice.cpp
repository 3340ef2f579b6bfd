// SPDX-License-Identifier: MIT
#include "state/practice/practice.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <locale>
#include <sstream>
#include <stdexcept>

#include "state/practice/practice_random.h"

namespace hsr::viz::practice {

std::span<const Topic> topics() {
    static const std::vector<Topic> all = [] {
        std::vector<Topic> t;
        for (auto family : {clipping_topics, backface_topics, bsp_topics, zbuffer_topics, precision_topics, scanline_topics, raycast_topics,
                            culling_topics, hiz_topics, depth_sort_topics,
                            portal_topics, horizon_topics, compositing_topics, perspective_topics})
            for (Topic& topic : family()) t.push_back(std::move(topic));
        return t;
    }();
    return all;
}

std::vector<algo::Saying> practice_sayings() {
    std::vector<algo::Saying> all;
    for (const Topic& t : topics())
        for (const auto group : t.sayings)  // topics share some (the pixel triangles)
            for (const algo::Saying& s : group)
                if (std::none_of(all.begin(), all.end(), [&](const algo::Saying& known) { return known.key == s.key; })) all.push_back(s);
    return all;
}

void Exercise::ask(Wording w) {
    question = english(w);
    asked = std::move(w);
}

void Exercise::offer(std::vector<Wording> words, std::size_t right) {
    choices.clear();
    for (const Wording& w : words) choices.push_back(english(w));
    answer = choices.at(right);
    offered = std::move(words);
}

const Wording* Exercise::choice(std::string_view english) const {
    for (std::size_t k = 0; k < choices.size() && k < offered.size(); ++k)
        if (choices[k] == english) return &offered[k];
    return nullptr;
}

const Topic* find_topic(std::string_view id) {
    for (const Topic& t : topics())
        if (t.id == id) return &t;
    return nullptr;
}

Exercise exercise(const Topic& topic, std::uint64_t series, std::uint64_t index, Level level) {
    // A drawn scene may be degenerate (a point on a plane, a triangle with no area) or its question empty (no
    // stage that cuts): draw again from the next seed. The makers reject a few draws in ten; 200 in a row is a bug.
    constexpr int redraws = 200;
    std::uint64_t seed = exercise_seed(series, index);
    for (int attempt = 0; attempt < redraws; ++attempt) {
        if (std::optional<Exercise> e = topic.make({seed, level})) {
            e->topic = std::string(topic.id);
            e->series = series;
            e->index = index;
            e->level = level;
            return *e;
        }
        seed = Dice(seed).next();
    }
    throw std::runtime_error("practice " + std::string(topic.id) + ": no exercise after " + std::to_string(redraws) +
                             " draws (series " + std::to_string(series) + ", exercise " + std::to_string(index + 1) + ")");
}

namespace {
std::string_view trimmed(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\n' || s.back() == '\r')) s.remove_suffix(1);
    return s;
}
std::optional<double> number(std::string_view s) {
    std::string text(s);
    for (char& c : text)
        if (c == ',') c = '.';  // 0,25 as German and many other languages write it
    if (text.rfind("−", 0) == 0) text.replace(0, std::string("−").size(), "-");
    // the whole reply a number in the C locale's way (a stream: the browser build's C++ library has no
    // std::from_chars for double); no sign but the minus, as from_chars would take
    if (text.empty() || text.front() == '+' || std::isspace(static_cast<unsigned char>(text.front()))) return std::nullopt;
    std::istringstream in(text);
    in.imbue(std::locale::classic());
    double v = 0;
    in >> v;
    if (in.fail() || in.peek() != std::char_traits<char>::eof() || !std::isfinite(v)) return std::nullopt;
    return v;
}
}  // namespace

std::string lesson_toml(const Exercise& e, std::string_view scene_file, const std::map<std::string, std::string>& titles) {
    std::string t = "# Written by hsrviz's practice: exercise " + std::to_string(e.index + 1) + " of series " + std::to_string(e.series) + "\n";
    if (titles.empty()) {
        t += "title = \"Practice: " + e.topic + ", series " + std::to_string(e.series) + ", exercise " + std::to_string(e.index + 1) + "\"\n";
    } else {  // a JSON string is a TOML basic string
        std::vector<std::string> languages;  // English first: a lesson's first language is what the command line says
        if (titles.contains("en")) languages.push_back("en");
        for (const auto& [language, title] : titles)
            if (language != "en") languages.push_back(language);
        t += "languages = " + nlohmann::json(languages).dump() + "\n";
        for (const auto& [language, title] : titles) t += "title." + language + " = " + nlohmann::json(title).dump() + "\n";
    }
    t += "algorithm = \"" + e.algorithm + "\"\n";
    t += "scene = \"" + std::string(scene_file) + "\"\n";
    if (!e.cull.empty()) t += "cull = \"" + e.cull + "\"\n";
    if (e.columns > 0) t += "grid = [" + std::to_string(e.columns) + ", 12]\n";
    return t;
}

bool grade(const Exercise& e, std::string_view reply) {
    reply = trimmed(reply);
    if (e.choices.empty()) {
        const auto got = number(reply), want = number(e.answer);
        return got && want && std::abs(*got - *want) <= e.tolerance + 1e-9;
    }
    // a reply that is a choice is that choice (an outcode such as 000001 is no choice's number)
    if (std::find(e.choices.begin(), e.choices.end(), reply) != e.choices.end()) return reply == e.answer;
    int k = 0;
    const auto [end, error] = std::from_chars(reply.data(), reply.data() + reply.size(), k);
    return error == std::errc() && end == reply.data() + reply.size() && k >= 1 && std::size_t(k) <= e.choices.size() &&
           e.choices[std::size_t(k - 1)] == e.answer;
}

std::string number_text(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

std::string decimal_text(double v, int digits) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", digits, v);
    std::string t = text;
    if (t.find('.') != std::string::npos) {
        while (t.back() == '0') t.pop_back();
        if (t.back() == '.') t.pop_back();
    }
    return t == "-0" ? "0" : t;
}

nlohmann::ordered_json to_json(const Exercise& e) {
    nlohmann::ordered_json j;
    j["topic"] = e.topic;
    j["series"] = e.series;
    j["exercise"] = e.index + 1;  // numbered from 1, as the window and the saved files number them
    j["level"] = int(e.level);
    j["question"] = e.question;
    if (!e.choices.empty()) j["choices"] = e.choices;
    j["answer"] = e.answer;
    if (e.choices.empty()) j["tolerance"] = e.tolerance;
    j["algorithm"] = e.algorithm;
    j["deciding_step"] = e.deciding_step;
    j["deciding"] = e.deciding;
    j["given"] = e.given;
    return j;
}

}  // namespace hsr::viz::practice
