// SPDX-License-Identifier: MIT
#include "frame_capture.h"

#include <SDL.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <string>

#include "capture.h"
#include "page_queries.h"
#include "panels/layout_audit.h"
#include "platform.h"
#include "state/output_folder.h"
#include "state/strings.h"
#include "state/trace.h"

namespace hsr::viz {

bool FrameCapture::begin(LessonPlay& lp, const AppOptions& o, int& exit_code) {
    frame_start_ = SDL_GetPerformanceCounter();
    bool runs = true;
    if (o.gif && lp.session()) {
        lp.session()->seek(o.gif_from);
        if (lp.session()->cursor() < o.gif_from) {  // a GIF of one frame, the last, would not be what was asked
            std::fprintf(stderr, "hsrviz: --from %zu is past the lesson's last step (%zu); the GIF would have no steps\n", o.gif_from,
                         lp.session()->cursor());
            exit_code = 2, runs = false;
        }
    }
    record_folder_made_ = !o.record_dir || make_folder(*o.record_dir);
    if (!record_folder_made_) exit_code = 1, runs = false;  // said why
    return runs;
}

void FrameCapture::after_draw(LessonPlay& lp, const AppOptions& o, std::uint64_t frame, int width, int height, bool keys_pressed,
                              bool& running, int& exit_code) {
    if (o.record_dir) {
        char name[64];
        std::snprintf(name, sizeof name, "/frame_%04llu.png", static_cast<unsigned long long>(frame - 1));
        write_png(*o.record_dir + name, width, height);
        if (!lp.session() || lp.session()->at_end() || frame >= 2000) running = false;
    }
    if (lp.export_pending && lp.session()) {
        lp.export_pending = false;
        std::vector<std::string> written;
        const auto edited = lp.with_family_screen([](const auto& s, const auto& screen) { return screen.edited_scene(s); });
        lp.tell(export_lesson(*lp.session(), lp.path, lp.algorithm, edited, width, height, written));
        for (const std::string& file : written) offer_download(file);
    }
    if (o.gif) {
        if (!gif_ && !gif_failed_) {
            gif_.emplace(*o.gif, o.gif_half ? width / 2 : width, o.gif_half ? height / 2 : height, 50);
            if (!gif_->ok()) std::fprintf(stderr, "hsrviz: cannot write %s\n", o.gif->c_str()), gif_.reset(), gif_failed_ = true, exit_code = 1;
        }
        if (gif_) gif_->add_frame(frame_pixels(width, height, o.gif_half));
        if (!gif_ || !lp.session() || lp.session()->at_end() || lp.session()->cursor() >= o.gif_to) running = false;
    }
    // the screenshot waits for every scripted key to be pressed and for R's measurement to be in, then (a few frames
    // at most) for the panel column to settle
    const std::uint64_t ready = std::max<std::uint64_t>(std::uint64_t(o.frames), o.keys.size());
    const bool settled = !lp.column.moved() && layout_problems().empty();
    if (!o.screenshot || !keys_pressed || frame < ready || (!settled && frame < ready + 8)) return;
    if (lp.session()) {
        std::printf("hsrviz: at %s\n", player_state(lp).c_str());
        std::printf("hsrviz: played trace %s\n", played_trace_text(*lp.session()).c_str());
    }
    if (lp.session() && lp.classroom.questions() > 0)
        std::printf("hsrviz: score %d of %d answered, %d questions, language %s\n", lp.classroom.right(), lp.classroom.answered(),
                    lp.classroom.questions(), lp.classroom.language().c_str());
    std::printf("hsrviz: window words %s, narration %s\n", window_strings().language().c_str(), lp.classroom.language().c_str());
    for (const std::string& problem : layout_problems()) std::printf("hsrviz: layout: %s\n", problem.c_str());
    for (const std::string& box : scrolling_boxes()) std::printf("hsrviz: scrolls: %s\n", box.c_str());
    if (result_scrolls() && lp.session() && lp.session()->complete() && lp.session()->cursor() >= lp.session()->known())
        std::printf("hsrviz: result scrolls: the lesson's state box scrolls at the end of the lesson\n");
    for (const Toasts::Showing& n : lp.toasts.showing(seconds_now())) std::printf("hsrviz: note showing: %s\n", n.text.c_str());
    if (!write_png(*o.screenshot, width, height)) {
        std::fprintf(stderr, "hsrviz: cannot write %s\n", o.screenshot->c_str());
        exit_code = 1;
    }
    if (!lp.session()) exit_code = 1;  // the picture shows the error; the exit says the lesson did not load
    running = false;
}

void FrameCapture::after_swap(const AppOptions& o) {
    if (!o.frame_log) return;
    const std::uint64_t now = SDL_GetPerformanceCounter();  // from the start of one frame to the start of the next
    frame_ms_.push_back(1000.0 * double(now - frame_start_) / double(SDL_GetPerformanceFrequency()));
    frame_start_ = now;
}

void FrameCapture::finish(const LessonPlay& lp, const AppOptions& o, std::uint64_t frames, int& exit_code) {
    if (o.frame_log && !frame_ms_.empty()) {
        std::ofstream log(*o.frame_log);
        for (double ms : frame_ms_) log << ms << '\n';
        if (!log.flush()) std::fprintf(stderr, "hsrviz: cannot write %s\n", o.frame_log->c_str()), exit_code = 1;
        std::vector<double> sorted = frame_ms_;
        std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(sorted.size() / 2), sorted.end());
        std::printf("hsrviz: %zu frames, median %.2f ms, written to %s\n", frame_ms_.size(), sorted[sorted.size() / 2], o.frame_log->c_str());
    }
    if (gif_) {
        const int written = gif_->frames();
        if (!gif_->close()) exit_code = 1;
        std::printf("hsrviz: wrote %d frames to %s\n", written, o.gif->c_str());
    }
    if (o.gif && !lp.session()) exit_code = 1;
    if (o.record_dir && record_folder_made_) {
        std::printf("hsrviz: wrote %llu frames to %s/frame_*.png\n", static_cast<unsigned long long>(frames), o.record_dir->c_str());
        if (!lp.session()) exit_code = 1;
    }
}

}  // namespace hsr::viz
