// SPDX-License-Identifier: MIT
#include "state/course.h"

#include <algorithm>
#include <exception>
#include <filesystem>

#include "state/families.h"
#include "state/lesson.h"

namespace hsr::viz {

std::vector<CourseLesson> load_course() {
    std::vector<CourseLesson> course;
    for (const std::string& path : shipped_lessons()) {
        CourseLesson c{path, std::filesystem::path(path).filename().string()};
        try {
            const Lesson l = load_lesson(path);
            c.title = l.title, c.titles = l.titles, c.languages = l.languages, c.algorithm = std::string(l.algorithm.id), c.difficulty = l.difficulty;
            c.prerequisites = l.prerequisites;
            c.topic = std::string(with_family(l.algorithm, [](auto family) { return decltype(family)::Session::facts.topic; }));
        } catch (const std::exception& e) {
            c.title = c.file, c.titles = {{"en", c.file}}, c.languages = {"en"};
            c.topic = "Lessons that cannot be loaded", c.problem = e.what();
        }
        course.push_back(std::move(c));
    }
    return course;
}

std::vector<CourseTopic> topics_of(const std::vector<CourseLesson>& course) {
    std::vector<CourseTopic> topics;
    for (const CourseLesson& l : course) {
        auto t = std::find_if(topics.begin(), topics.end(), [&](const CourseTopic& x) { return x.name == l.topic; });
        if (t == topics.end()) t = topics.insert(topics.end(), CourseTopic{l.topic, {}});
        t->lessons.push_back(&l);
    }
    return topics;
}

}  // namespace hsr::viz
