// SPDX-License-Identifier: MIT
#include "state/settings_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <vector>

namespace hsr::viz {

std::string replace_file(const std::string& path, const std::string& text) {
    std::vector<char> temporary(path.begin(), path.end());
    for (const char c : std::string(".new-XXXXXX")) temporary.push_back(c);
    temporary.push_back('\0');
    const int fd = ::mkstemp(temporary.data());  // O_CREAT | O_EXCL: a new file of its own, never a link followed
    if (fd < 0) return "cannot make a new file beside " + path + ": " + std::strerror(errno);
    (void)::fchmod(fd, 0644);  // as a file written by any program (mkstemp makes 0600)
    const auto fail = [&](const char* doing) {
        const std::string why = std::string("cannot ") + doing + " " + path + ": " + std::strerror(errno);
        ::close(fd);
        ::unlink(temporary.data());
        return why;
    };
    for (std::size_t at = 0; at < text.size();) {
        const ssize_t n = ::write(fd, text.data() + at, text.size() - at);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return fail("write");
        at += std::size_t(n);
    }
    if (::fsync(fd) != 0 && errno != EINVAL) return fail("write");  // a full disk on a network folder shows here
    if (::close(fd) != 0) {
        const std::string why = "cannot write " + path + ": " + std::strerror(errno);
        ::unlink(temporary.data());
        return why;
    }
    if (::rename(temporary.data(), path.c_str()) != 0) {
        const std::string why = "cannot replace " + path + ": " + std::strerror(errno);
        ::unlink(temporary.data());
        return why;
    }
    return "";
}

std::string keep_aside(const std::string& path, std::string& why) {
    const std::string kept = path + ".bak";
    // link() never replaces: an existing PATH.bak (an older broken file, or the user's own) stays as it is
    if (::link(path.c_str(), kept.c_str()) == 0) {
        if (::unlink(path.c_str()) == 0) return kept;
        why = std::string("cannot remove it after keeping it as ") + kept + ": " + std::strerror(errno);
        return "";
    }
    if (errno == EEXIST) {
        why = kept + " exists already";
        return "";
    }
    // a file system without hard links: a rename, still never over a file there
    std::error_code ec;
    if (std::filesystem::exists(std::filesystem::symlink_status(kept, ec))) {
        why = kept + " exists already";
        return "";
    }
    if (::rename(path.c_str(), kept.c_str()) == 0) return kept;
    why = std::strerror(errno);
    return "";
}

}  // namespace hsr::viz
