// SPDX-License-Identifier: MIT
// The course: the shipped lessons in order, each with what the lesson menu shows (its topic from the lecture,
// difficulty, prerequisites), and what `hsrviz --lesson-list` prints.
#pragma once

#include <string>
#include <vector>

#include "state/chapters.h"

namespace hsr::viz {

struct CourseLesson {
    std::string path, file;  // file: "05_bsp_traversal.toml"
    std::string title, topic, algorithm;  // title in the lesson's first language
    Texts titles;                          // by language
    std::vector<std::string> languages;
    int difficulty = 0;
    std::vector<std::string> prerequisites;  // lesson file names
    std::string problem;                     // why it cannot be loaded ("" when it can): listed, never hidden
};

std::vector<CourseLesson> load_course();

// The topics in the course's order (of their first lesson), each with its lessons in order.
struct CourseTopic {
    std::string name;
    std::vector<const CourseLesson*> lessons;
};
std::vector<CourseTopic> topics_of(const std::vector<CourseLesson>& course);

}  // namespace hsr::viz
