// SPDX-License-Identifier: MIT
#include "cli/commands.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <new>

#include "registry.h"
#include "scene/input_file.h"
#include "state/course.h"
#include "state/lesson.h"
#include "state/lesson_check.h"
#include "state/trace.h"

namespace hsr::viz {

std::string algorithm_ids_by_family() {
    std::string out;
    std::size_t family = std::variant_npos;
    for (const algo::AlgorithmInfo& a : algo::algorithms()) {
        if (!out.empty()) out += a.machine.index() == family ? ", " : "; ";
        out += a.id;
        family = a.machine.index();
    }
    return out;
}

int print_lesson_list() {
    int status = 0;
    for (const CourseLesson& l : load_course()) {
        if (!l.problem.empty()) {  // listed with its problem: the menu must not hide a broken lesson
            std::printf("%-32s -  %-26s (cannot be loaded: %s)\n", l.file.c_str(), "?", l.problem.c_str());
            status = 1;
            continue;
        }
        std::printf("%-32s %d  %-26s %-20s %s\n", l.file.c_str(), l.difficulty, l.algorithm.c_str(), l.topic.c_str(), l.title.c_str());
    }
    return status;
}

int run_check(std::vector<std::string> files, const std::string& root) {
    if (files.empty())
        for (const char* dir : {"lessons", "assets/scenes"}) {
            std::error_code ec;
            const std::filesystem::path folder = std::filesystem::path(root) / dir;
            for (auto it = std::filesystem::recursive_directory_iterator(folder, ec); !ec && it != std::filesystem::end(it); it.increment(ec))
                if (it->path().extension() == ".toml") files.push_back(it->path().string());
            if (ec) {  // an installation without its data, or HSRVIZ_DATA naming the wrong folder
                std::fprintf(stderr, "hsrviz: cannot read the shipped lessons and scenes in %s: %s (set HSRVIZ_DATA to the "
                                     "folder holding lessons/ and assets/)\n", algo::printable(folder.string()).c_str(), ec.message().c_str());
                return 1;
            }
        }
    std::sort(files.begin(), files.end());
    int bad = 0;
    for (const std::string& f : files) {
        const CheckResult r = check_file(f);
        for (const std::string& w : r.warnings) std::printf("warn  %s\n", algo::printable(w, 2000).c_str());
        if (r.problems.empty()) {
            std::printf("ok    %s (%zu events, %zu chapters, %zu questions)\n", algo::printable_name(f).c_str(), r.events, r.chapters, r.questions);
            continue;
        }
        ++bad;
        std::printf("FAIL  %s\n", algo::printable_name(f).c_str());
        for (const std::string& p : r.problems) std::printf("      %s\n", algo::printable(p, 2000).c_str());
    }
    std::printf("%zu files checked, %d with problems\n", files.size(), bad);
    return bad == 0 ? 0 : 1;
}

int with_stdout_checked(int code) {
    errno = 0;
    if (std::fflush(stdout) == 0 && !std::ferror(stdout)) return code;
    std::fprintf(stderr, "hsrviz: cannot write the standard output%s%s\n", errno ? ": " : "", errno ? std::strerror(errno) : "");
    return code == 0 ? 1 : code;
}

}  // namespace hsr::viz
