// SPDX-License-Identifier: MIT
// hsrviz: step through culling and hidden-surface algorithms.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <tuple>

#include "app.h"
#include "cli/commands.h"
#include "cli/option_ranges.h"
#include "state/output_folder.h"
#include "cli/render_command.h"
#include "cli/practice_command.h"
#include "cli/report_command.h"
#include "state/arguments.h"
#include "state/lesson.h"
#include "state/trace.h"
#include "scene/renderer_names.h"

int main(int argc, char** argv) {
    // Command line: the window by default, `trace` for a headless run.
    CLI::App cli{"hsrviz: a step-through visualizer of culling and hidden-surface algorithms"};
    hsr::viz::AppOptions app;
    std::string size = "1280x800";
    constexpr std::uint64_t max_step = 100'000'000;  // --from, --to: far beyond any lesson's steps
    cli.add_option("lesson", app.lesson_path, "Lesson or scene file to play (default: the Cohen–Sutherland lesson)");
    cli.add_option("--screenshot", app.screenshot, "Take one Step per frame, write a PNG of the window after --frames, exit");
    cli.add_option("--frames", app.frames, "Frames to play before the screenshot")->check(hsr::viz::whole_from(1, 1000000));
    cli.add_option("--gif", app.gif, "Write an animated GIF of the window for steps --from to --to (one frame a step), then exit");
    cli.add_option("--from", app.gif_from, "First step of the GIF (default 0)")->check(hsr::viz::whole_from(0, max_step));
    cli.add_option("--to", app.gif_to, "Last step of the GIF (default 60)")->check(hsr::viz::whole_from(0, max_step));
    cli.add_flag("--gif-half", app.gif_half, "GIF frames at half the window's size (smaller files; text is harder to read)");
    cli.add_option("--record", app.record_dir, "Play the lesson to its end, writing a PNG per step into this folder");
    cli.add_option("--algorithm", app.algorithm, "Play the lesson with another algorithm of its family (families apart by ';'): " + hsr::viz::algorithm_ids_by_family());
    CLI::Option* size_option = cli.add_option("--size", size, "Window size WxH (default: as the last run left it, else 1280x800)")->check(CLI::Validator(
        [](std::string& s) { return hsr::viz::parse_size(s, 16384) ? "" : "expected WxH, each from 1 to 16384"; }, "WxH"));
    cli.add_flag("--play", app.autoplay, "Start playing at once");
    bool lesson_list = false;
    cli.add_flag("--lesson-list", lesson_list, "Print the shipped lessons in the course's order (file, difficulty, algorithm, title), then exit");
    cli.add_option("--frame-log", app.frame_log, "Write each frame's time (ms) to this file; print the median at exit");
    cli.add_option("--scale", app.scale, "Size of type and panels, 0.5 to 4 (default: 1.3 with --projector, the screen's on a high-DPI screen, else 1; Ctrl+= and Ctrl+- change it)")
        ->check(hsr::viz::number_from(0.5, 4));
    cli.add_flag("--projector", app.projector, "Projector mode: fullscreen, larger type for the back row, high contrast (F1: keys)");
    std::string keys;  // one comma-separated argument: a lesson after it is the lesson, not one more key
    cli.add_option("--keys", keys, "Keys to press, one per frame, comma-separated (Space,Right,Shift+Right,Left,Home,End,F5,V,1); "
                                   "with --screenshot, the keys alone move the player");

    hsr::viz::TraceOptions trace;
    CLI::App* trace_cmd = cli.add_subcommand("trace", "Run a lesson's machine headless to completion and write its trace");
    trace_cmd->add_option("input", trace.input, "Lesson or scene file")->required();  // a missing file: the loader says why
    trace_cmd->add_option("--out", trace.out, "JSON Lines file to write (one event per line)")->required();
    trace_cmd->add_option("--algorithm", trace.algorithm, "Override the lesson's algorithm");
    std::vector<std::string> check_files;
    CLI::App* check_cmd = cli.add_subcommand("check", "Validate lessons and scenes: schema, references, chapters, questions");
    check_cmd->add_option("files", check_files, "Lesson or scene files (default: every shipped one)");
    hsr::viz::RenderOptions render;
    CLI::App* render_cmd = cli.add_subcommand("render", "Render a scene headless with a hidden-surface algorithm");
    render_cmd->add_option("scene", render.scene, "Scene file (world coordinates), or a generated scene: city:N, field:N, spheres:N (N triangles)")->required();
    render_cmd->add_option("--algorithm", render.algorithm, "Hidden-surface algorithm: " + hsr::algo::renderer_list(true, ", "));
    render_cmd->add_option("--format", render.format, "Depth format for zbuffer and scanline: int16, int24 (default), int32, float32, float32-reversed, linear24");
    render_cmd->add_option("--accel", render.acceleration, "Ray cast acceleration: none, grid (default), octree, bvh");
    render_cmd->add_option("--splitter", render.splitter, "BSP splitter rule: first, balanced, fewest-splits, weighted");
    render_cmd->add_option("--cull", render.cull, "zbuffer: culling stages first, from back-face,frustum,detail,occluders,portals,hiz");
    render_cmd->add_option("--occluders", render.occluders, "The occluders stage's shapes: planar (default), proxy, solid (Papaioannou's, with planar)");
    render_cmd->add_flag("--fusion", render.fusion, "The occluders stage fuses its occluders (a box hidden by several together is culled)");
    render_cmd->add_option("--eye", render.eye, "Eye position X,Y,Z (default: the scene camera's)");
    render_cmd->add_option("--size", render.size, "Image size WxH (default 512x512)");
    render_cmd->add_option("--out", render.out, "Colour image (PNG)")->required();
    render_cmd->add_option("--ids", render.ids, "Visible primitive id per pixel (16-bit grey PNG, 0 = background)");
    hsr::viz::ReportOptions report;
    CLI::App* report_cmd = cli.add_subcommand("report", "Measure error against run time for every algorithm family; write Markdown, CSV and SVG charts");
    report_cmd->add_option("--out", report.out, "Folder to write report.md, report.csv and one chart per family into");
    report_cmd->add_flag("--quick", report.quick, "Small scenes and three repeats (about a minute)");
    report_cmd->add_option("--repeats", report.repeats, "Runs per measurement; the median is reported")->check(hsr::viz::whole_from(1, 1000));
    hsr::viz::PracticeOptions practice;
    CLI::App* practice_cmd = cli.add_subcommand("practice", "Print exercises of a topic as JSON Lines: the same seed, the same exercises");
    practice_cmd->add_option("topic", practice.topic, "Topic (cohen_sutherland, liang_barsky, sutherland_hodgman, backface, …; 'list' lists them)")->required();
    practice_cmd->add_option("--seed", practice.seed, "Series of exercises (a teacher hands out its number)")
        ->check(hsr::viz::whole_from(0, UINT64_MAX));
    practice_cmd->add_option("--count", practice.count, "How many exercises")->check(hsr::viz::whole_from(1, 1000000));
    practice_cmd->add_option("--level", practice.level, "1 easy, 2 medium, 3 hard (close to degenerate)")->check(hsr::viz::whole_from(1, 3));
    cli.set_version_flag("--version", "hsrviz " HSR_VERSION);
    try {
        cli.parse(argc, argv);
    } catch (const CLI::ParseError& e) {  // --help and --version end here too, with 0; a usage error exits 2
        const int code = cli.exit(e);
        return hsr::viz::with_stdout_checked(code == 0 ? 0 : 2);
    }

    if (app.gif && app.gif_from > app.gif_to) {
        std::fprintf(stderr, "hsrviz: --from %zu is after --to %zu; the GIF would have no steps\n", app.gif_from, app.gif_to);
        return 2;
    }
    if (*trace_cmd) return hsr::viz::with_stdout_checked(hsr::viz::run_trace(trace));
    if (*check_cmd) return hsr::viz::with_stdout_checked(hsr::viz::run_check(check_files, hsr::viz::data_dir()));
    if (*render_cmd) return hsr::viz::with_stdout_checked(hsr::viz::run_render(render));
    if (*report_cmd) return hsr::viz::with_stdout_checked(hsr::viz::run_report(report));
    if (*practice_cmd) return hsr::viz::with_stdout_checked(hsr::viz::run_practice(practice));

    // The window: the default lesson unless one is named.
    if (app.lesson_path.empty()) app.lesson_path = hsr::viz::default_lesson_path();
    std::tie(app.width, app.height) = *hsr::viz::parse_size(size, 16384);
    app.size_given = size_option->count() > 0;
    if (lesson_list) return hsr::viz::with_stdout_checked(hsr::viz::print_lesson_list());
    for (std::size_t at = 0; !keys.empty() && at <= keys.size();) {
        const std::size_t comma = std::min(keys.find(',', at), keys.size());
        app.keys.push_back(keys.substr(at, comma - at));
        at = comma + 1;
    }

    // No display: say so, and play the same lesson headless through SDL's offscreen driver (EGL on Mesa).
    const bool no_display = !std::getenv("DISPLAY") && !std::getenv("WAYLAND_DISPLAY") && !std::getenv("SDL_VIDEODRIVER");
    if (no_display) {
        setenv("SDL_VIDEODRIVER", "offscreen", 1);
        if (!app.screenshot && !app.record_dir && !app.gif) {
            app.record_dir = hsr::viz::output_folder("hsrviz-out");
            const std::string trace_file = *app.record_dir + "/trace.jsonl";
            std::printf("hsrviz: no display found; playing %s headless, writing frames to %s/frame_*.png and the trace to %s\n",
                        app.lesson_path.c_str(), app.record_dir->c_str(), trace_file.c_str());
            if (!hsr::viz::make_folder(*app.record_dir)) return 1;
            if (hsr::viz::run_trace({app.lesson_path, trace_file, app.algorithm}) != 0) return 1;
        }
    }
    return hsr::viz::with_stdout_checked(hsr::viz::run_app(app));
}
