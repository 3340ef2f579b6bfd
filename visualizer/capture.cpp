// SPDX-License-Identifier: MIT
#include "capture.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "state/output_folder.h"
#include "state/trace.h"
#include "state/trace_file.h"
#include "state/png_io.h"
#include "render/gl.h"
#include "scene/save_scene.h"

namespace hsr::viz {
namespace {

std::vector<unsigned char> read_pixels(int w, int h) {
    std::vector<unsigned char> pixels(std::size_t(w) * std::size_t(h) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    return pixels;  // GL's rows run bottom up
}

}  // namespace

std::vector<unsigned char> frame_pixels(int w, int h, bool half) {
    const std::vector<unsigned char> full = read_pixels(w, h);
    const int f = half ? 2 : 1, fw = w / f, fh = h / f;  // each pixel of the frame averages f × f of the window's
    std::vector<unsigned char> out(std::size_t(fw) * std::size_t(fh) * 4);
    for (int y = 0; y < fh; ++y)
        for (int x = 0; x < fw; ++x)
            for (int c = 0; c < 4; ++c) {
                int sum = 0;
                for (int dy = 0; dy < f; ++dy)
                    for (int dx = 0; dx < f; ++dx)  // GL's rows run bottom up: flip
                        sum += full[(std::size_t(h - 1 - (f * y + dy)) * std::size_t(w) + std::size_t(f * x + dx)) * 4 + std::size_t(c)];
                out[(std::size_t(y) * std::size_t(fw) + std::size_t(x)) * 4 + std::size_t(c)] = static_cast<unsigned char>(sum / (f * f));
            }
    return out;
}

bool write_png(const std::string& path, int w, int h) {
    const std::vector<unsigned char> pixels = read_pixels(w, h);
    return write_png(path, w, h, 4, pixels.data(), true);
}

std::string export_lesson(const Session& s, const std::string& path, const std::optional<std::string>& algorithm,
                          const std::optional<algo::Scene>& edited, int width, int height, std::vector<std::string>& written) {
    const std::string dir = output_folder("hsrviz-export"), stem = std::filesystem::path(s.lesson().source).stem().string();
    if (!make_folder(dir)) return "could not make the folder " + dir;
    const std::string png = dir + "/" + stem + "-step-" + std::to_string(s.cursor()) + ".png";
    const std::string trace = dir + "/" + stem + ".jsonl", scene = dir + "/" + stem + "-scene.toml";
    // after an edit, the scene and the trace of what the window shows: the edited scene run through the machine
    const auto write_trace = [&] {
        if (!edited) return run_trace({path, trace, algorithm}) == 0;
        Lesson lesson = s.lesson();
        lesson.scene = *edited;
        std::ofstream out(trace);
        trace_lesson(lesson, &out);
        return static_cast<bool>(out);
    };
    const bool ok = write_png(png, width, height) && write_trace() &&
                    static_cast<bool>(std::ofstream(scene) << "# exported by hsrviz " HSR_VERSION " at step " << s.cursor() << "\n"
                                                            << algo::scene_toml(edited ? *edited : s.lesson().scene));
    if (ok) written = {png, trace, scene};
    return std::string(ok ? "exported " : "could not export all of ") + png + ", " + trace + " and " + scene;
}

}  // namespace hsr::viz
