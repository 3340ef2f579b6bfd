// SPDX-License-Identifier: MIT
// Notices when the files a lesson came from change on disk (a teacher editing the lesson or its scene while the
// window shows it), by their modification times, looked at no more than twice a second.
#pragma once

#include <filesystem>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace hsr::viz {

class FileWatch {
public:
    void watch(const std::vector<std::string>& files) {
        files_.clear();
        for (const std::string& f : files) files_.push_back({f, stamp(f)});
    }
    // The files watched now, by name.
    std::vector<std::string> files() const {
        std::vector<std::string> out;
        for (const auto& [file, time] : files_) out.push_back(file);
        return out;
    }
    // True once per change (after the files settled at their new times).
    bool changed(double dt) {
        since_ += dt;
        if (since_ < 0.5) return false;
        since_ = 0;
        bool any = false;
        for (auto& [file, time] : files_)
            if (const auto now = stamp(file); now != time) time = now, any = true;
        return any;
    }

private:
    static std::filesystem::file_time_type stamp(const std::string& f) {
        std::error_code ec;  // a file being rewritten may be missing for a moment: that is a change too
        const auto t = std::filesystem::last_write_time(f, ec);
        return ec ? std::filesystem::file_time_type::min() : t;
    }
    std::vector<std::pair<std::string, std::filesystem::file_time_type>> files_;
    double since_ = 0;
};

}  // namespace hsr::viz
