// SPDX-License-Identifier: MIT
#include "scene/input_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "scene/toml_reader.h"

namespace hsr::algo {
namespace {

// A file's size as a person reads it: "70 KB", "65 MB" (a settings file's 64 KB was "0 MB").
std::string megabytes(std::size_t bytes) {
    char s[32];
    if (bytes < (std::size_t(1) << 20)) std::snprintf(s, sizeof s, "%zu KB", (bytes + 1023) >> 10);
    else std::snprintf(s, sizeof s, "%.0f MB", double(bytes) / double(1 << 20));
    return s;
}

// Closes the descriptor on every way out.
struct Descriptor {
    int fd;
    ~Descriptor() {
        if (fd >= 0) ::close(fd);
    }
};

}  // namespace

std::string read_input_file(const std::string& path, std::size_t limit) {
    const auto fail = [&](const std::string& why) -> LoadError { return LoadError(path, 0, 0, "", why); };
    // O_NONBLOCK: opening a FIFO for reading would wait for a writer; this way it opens at once and is refused below.
    const Descriptor d{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY)};
    if (d.fd < 0) throw fail(std::string("cannot open the file: ") + std::strerror(errno));
    struct stat st {};
    if (::fstat(d.fd, &st) != 0) throw fail(std::string("cannot read the file: ") + std::strerror(errno));
    if (S_ISDIR(st.st_mode)) throw fail("is a folder, not a file");
    if (!S_ISREG(st.st_mode))
        throw fail(std::string("is not a regular file (it is a ") +
                   (S_ISFIFO(st.st_mode) ? "FIFO" : S_ISSOCK(st.st_mode) ? "socket" : "device") +
                   "); hsrviz reads only regular files");
    if (std::size_t(st.st_size) > limit)
        throw fail("is " + megabytes(std::size_t(st.st_size)) + "; hsrviz reads files up to " + megabytes(limit));
    std::string text;
    char buffer[1 << 16];
    for (;;) {  // to the end, not to st_size: a file may grow while it is read, or report size 0 (/proc)
        const ssize_t n = ::read(d.fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) throw fail(std::string("cannot read the file: ") + std::strerror(errno));
        if (n == 0) break;
        text.append(buffer, std::size_t(n));
        if (text.size() > limit) throw fail("is more than " + megabytes(limit) + "; hsrviz reads files up to " + megabytes(limit));
    }
    if (text.empty()) throw fail("the file is empty");
    return text;
}

namespace {

std::string shown(std::string_view text, std::size_t max, bool one_line) {
    std::string out;
    const auto put = [&](std::string_view part) {
        for (const char c : part) {
            const auto u = static_cast<unsigned char>(c);
            if ((u < 0x20 && (one_line || (c != '\n' && c != '\t'))) || u == 0x7f) {
                char hex[8];
                std::snprintf(hex, sizeof hex, "\\x%02x", u);
                out += hex;
            } else {
                out += c;
            }
        }
    };
    if (text.size() <= max) {
        put(text);
        return out;
    }
    // Cut at UTF-8 character starts so no half character is shown.
    std::size_t head = max / 2, tail = text.size() - max / 2;
    while (head > 0 && (static_cast<unsigned char>(text[head]) & 0xC0) == 0x80) --head;
    while (tail < text.size() && (static_cast<unsigned char>(text[tail]) & 0xC0) == 0x80) ++tail;
    put(text.substr(0, head));
    out += " … (" + std::to_string(text.size()) + " bytes) … ";
    put(text.substr(tail));
    return out;
}

}  // namespace

std::string printable(std::string_view text, std::size_t max) { return shown(text, max, false); }
std::string printable_name(std::string_view name, std::size_t max) { return shown(name, max, true); }

}  // namespace hsr::algo
