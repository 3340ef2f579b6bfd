// [SECTION] the lesson and its playback (update)
// [SECTION] drawing a frame (draw)
// [SECTION] window, GL context and ImGui setup
// [SECTION] the loop
#include "app.h"

#include <SDL.h>
#include <imgui.h>
#include <imgui_impl_opengl3.h>
#include <imgui_impl_sdl.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <fstream>
#include <vector>

#include "panels/bsp_panels.h"
#include "panels/clip_panels.h"
#include "panels/cull_panels.h"
#include "panels/raycast_panels.h"
#include "panels/scanline_panels.h"
#include "panels/depth_sort_panels.h"
#include "panels/portal_panels.h"
#include "panels/culling_panels.h"
#include "panels/chapter_panels.h"
#include "panels/zbuffer_panels.h"
#include "panels/zmerge_panels.h"
#include "render/bsp_renderer.h"
#include "render/clip_renderer.h"
#include "render/cull_renderer.h"
#include "render/depth_sort_renderer.h"
#include "render/portal_renderer.h"
#include "render/culling_renderer.h"
#include "render/frustum.h"
#include "render/raycast_renderer.h"
#include "render/zbuffer_renderer.h"
#include "render/gl.h"
#include "render/orbit_camera.h"
#include "render/palette.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include "scene/toml_reader.h"
#include "state/bsp_session.h"
#include "state/clip_session.h"
#include "state/cull_session.h"
#include "state/depth_sort_session.h"
#include "state/portal_session.h"
#include "state/culling_session.h"
#include "state/raycast_session.h"
#include "state/scanline_session.h"
#include "state/zbuffer_session.h"
#include "state/zmerge_session.h"
#include "state/trace.h"
#include "state/classroom.h"
#include "state/file_watch.h"
#include "gif_writer.h"
#include "scripted_input.h"
#include "panels/preset_panel.h"
#include "state/presets.h"
#include "state/family_report.h"
#include "panels/report_panel.h"
#include "state/window_settings.h"
#include "cli/commands.h"
#include "scene/save_scene.h"

namespace hsr::viz {
namespace {

// ── [SECTION] the lesson and its playback (update) ──────────────────────────────────────────────────────────
struct Lessonplay {
    std::unique_ptr<Session> session;
    std::string error;  // why the lesson could not be loaded ("" when it could)
    PlaybackState playback;
    OrbitCamera camera;
    std::optional<ClipView> before;  // the view the picture is sliding from
    double tween = 1;                // 0 … 1 of the way from `before` to the current view
    static constexpr double tween_seconds = 0.25;
    bool animate = true;             // off for screenshots and recordings: they show each step as it ends
    bool zbuffer_3d = false;         // z-buffer and portal lessons: the scene in 3D instead of the pixels or the plan
    Classroom classroom;             // chapters, questions, language, score
    FileWatch watch;                 // the lesson and scene files: edited on disk, reloaded
    bool show_keys = false;          // F1
    bool export_pending = false;     // E: written after the next frame is drawn
    std::string home;                // the lesson the window was started with
    std::string path;                // what plays: the lesson, or a preset scene chosen with P
    std::optional<std::string> algorithm;
    bool show_presets = false;       // P
    float side = 500;                // the panel column's width ([ and ] change it; remembered)
    bool show_report = false;        // R: error against run time for the algorithm's family
    std::vector<analysis::Measurement> report;  // measured when R first opens it
    std::vector<Preset> presets;     // of the lesson's algorithm
    std::uint32_t next_seed = 1;     // of the next random scene

    void load(const AppOptions& o) {
        const std::size_t keep = session ? session->cursor() : 0;  // a reload stays at its step where it still exists
        if (path.empty()) home = path = o.lesson_path, algorithm = o.algorithm;
        watch.watch({path});
        try {
            const Lesson lesson = load_lesson(path, algorithm);
            presets = extreme_presets(lesson.algorithm, data_dir() + "/assets/scenes/extreme");
            if (session && session->lesson().algorithm.family != lesson.algorithm.family) report.clear();
            std::error_code ec;
            if (lesson.scene.source != path && std::filesystem::is_regular_file(lesson.scene.source, ec))
                watch.watch({path, lesson.scene.source});
            session = make_session(lesson);
            session->prefetch(prefetch_events);  // the scrub bar shows a lesson's whole length
            classroom.attach(*session);
            error.clear();
            before.reset();
            glm::vec3 centre(0);
            float radius = 1;
            if (const auto* clip = dynamic_cast<const ClipSession*>(session.get()))
                clip_view_bounds(clip->view(), clip->lesson().scene, centre, radius);
            if (const auto* cull = dynamic_cast<const CullSession*>(session.get()))
                cull_view_bounds(cull->view(), centre, radius);
            if (const auto* zb = dynamic_cast<const ZBufferSession*>(session.get())) scene_bounds(zb->lesson().scene, centre, radius);
            if (const auto* culling = dynamic_cast<const CullingLesson*>(session.get())) {
                culling_view_bounds(culling->culling_view(), centre, radius);
                camera.yaw = 0.6f, camera.pitch = 0.7f;  // from above and aside: the camera's frustum and what it leaves out
            }
            if (const auto* portals = dynamic_cast<const PortalRenderSession*>(session.get())) {
                portal_view_bounds(portals->view().world->model, centre, radius);
                camera.yaw = 0.3f, camera.pitch = 0.9f;  // from above, to look into the rooms (they have no ceilings)
            }
            if (dynamic_cast<const DepthSortSession*>(session.get())) {  // the canonical view volume, seen from the eye's side
                centre = glm::vec3(0), radius = 1.6f;
                camera.yaw = 0.55f, camera.pitch = 0.35f;
            }
            if (const auto* ray = dynamic_cast<const RayCastSession*>(session.get())) {
                scene_bounds(ray->scene(), centre, radius);
                camera.yaw = 0.9f, camera.pitch = 0.35f;  // from the side: the rays leave the eye across the view
            }
            if (const auto* bsp = dynamic_cast<const BspSession*>(session.get())) {
                bsp_view_bounds(bsp->view(), centre, radius);
                const glm::dvec3 from = bsp->lesson().scene.camera.eye - glm::dvec3(centre);
                if (bsp->view().two_d) {
                    camera.yaw = 0, camera.pitch = 0;  // face the plane z = 0
                } else if (glm::length(from) > 0) {  // look from where the scene's eye is, a little higher
                    const glm::dvec3 d = glm::normalize(from);
                    camera.yaw = float(std::atan2(d.x, d.z));
                    camera.pitch = float(std::clamp(std::asin(d.y) + 0.25, -1.4, 1.4));
                }
            }
            camera.target = centre;
            camera.distance = radius * 2.4f;
            session->seek(std::min(keep, session->known()));
        } catch (const std::exception& e) {  // a bad file shows its error instead of the scene
            session.reset();
            error = e.what();
            std::fprintf(stderr, "hsrviz: %s\n", e.what());
        }
    }

    // P: play another scene with the lesson's algorithm (an extreme case, a random scene), or go back to the lesson.
    void choose_preset(const UiActions& a, const AppOptions& o) {
        if (a.back_to_lesson) {
            path = o.lesson_path, algorithm = o.algorithm;
        } else if (a.preset && *a.preset >= 0 && std::size_t(*a.preset) < presets.size()) {
            if (session) algorithm = std::string(session->lesson().algorithm.id);
            path = presets[std::size_t(*a.preset)].file;
        } else if (a.random_scene && session) {
            const auto* bsp = dynamic_cast<const BspSession*>(session.get());
            const auto toml = random_scene_toml(session->lesson().algorithm, bsp && bsp->view().two_d, next_seed);
            if (!toml) return;
            algorithm = std::string(session->lesson().algorithm.id);
            std::filesystem::create_directories("hsrviz-export");
            path = "hsrviz-export/random-" + *algorithm + "-seed" + std::to_string(next_seed++) + ".toml";
            std::ofstream(path) << *toml;
        } else {
            return;
        }
        show_presets = false;
        session.reset();  // a new scene starts at its first step
        load(o);
        std::printf("hsrviz: playing %s with %s\n", path.c_str(), algorithm.value_or("the lesson's algorithm").c_str());
    }

    // S: the scene as edited, to hsrviz-export/NAME-edited.toml
    void save_edited(const algo::Scene& scene) const {
        const std::string file = "hsrviz-export/" + std::filesystem::path(path).stem().string() + "-edited.toml";
        std::filesystem::create_directories("hsrviz-export");
        const bool ok = static_cast<bool>(std::ofstream(file) << algo::scene_toml(scene));
        std::printf("hsrviz: %s %s\n", ok ? "saved the edited scene to" : "could not write", file.c_str());
    }

    void update(const UiActions& a, double dt, const AppOptions& o) {
        if (a.reload || watch.changed(dt)) load(o);
        if (a.toggle_presets) show_presets = !show_presets;
        if (a.toggle_report) {
            show_report = !show_report;
            if (show_report && session && report.empty()) {
                report = family_report(session->lesson().algorithm, data_dir() + "/assets/scenes");
                std::printf("hsrviz: measured %zu rows of error against run time for %s\n", report.size(),
                            std::string(session->lesson().algorithm.id).c_str());
            }
        }
        if (show_presets) {  // the presets take the number keys while they show: 1 … 9 a case, 0 a random scene
            UiActions pick = a;
            if (a.digit && *a.digit >= 1) pick.preset = *a.digit - 1;
            if (a.digit && *a.digit == 0) pick.random_scene = true;
            choose_preset(pick, o);
            if (show_presets && a.digit) return;
        } else if (a.preset || a.random_scene || a.back_to_lesson) {
            choose_preset(a, o);
        }
        if (!session) return;
        // the classroom: a number answers an open question (else 3 is the 3D key), chapters, language
        std::optional<std::string> answer = a.answer;
        bool toggle_3d = a.toggle_3d || (a.digit == 3 && !classroom.open_question(*session));
        if (a.digit)
            if (const Question* q = classroom.open_question(*session); q && *a.digit >= 1 && std::size_t(*a.digit) <= q->choices.size())
                answer = q->choices[std::size_t(*a.digit - 1)], toggle_3d = a.toggle_3d;
        if (answer) {
            if (const auto v = classroom.answer(*session, *answer))
                std::printf("hsrviz: answered \"%s\": %s, the machine says \"%s\"\n", answer->c_str(), v->right ? "right" : "wrong", v->answer.c_str());
            playback.playing = false;
        }
        if (a.next_chapter) classroom.next_chapter(*session), playback.playing = false;
        if (a.previous_chapter) classroom.previous_chapter(*session), playback.playing = false;
        if (a.next_language) classroom.next_language();
        if (a.toggle_keys) show_keys = !show_keys;
        side += a.column_wider ? 40.f : a.column_narrower ? -40.f : 0.f;
        if (a.export_all) export_pending = true;
        if (a.close_overlays) show_keys = show_presets = show_report = false;
        if (auto* bsp = dynamic_cast<BspSession*>(session.get())) {  // editing a 2D scene
            bool edited = false;
            if (a.move_vertex) bsp->move_vertex(a.move_vertex->input, a.move_vertex->vertex, a.move_vertex->to), edited = true;
            if (a.add_segment) edited |= bsp->add_segment(a.add_segment->first, a.add_segment->second);
            if (a.delete_input) edited |= bsp->delete_input(*a.delete_input);
            if (a.undo) edited |= bsp->undo();
            if (a.redo) edited |= bsp->redo();
            if (edited) classroom.attach(*session);
            if (a.save_scene) save_edited(bsp->edited_scene());
        }
        if (a.move_eye) {
            if (auto* bsp = dynamic_cast<BspSession*>(session.get())) bsp->move_eye(*a.move_eye);
            if (auto* portals = dynamic_cast<PortalRenderSession*>(session.get())) portals->move_eye(algo::plan_point(*a.move_eye));
            classroom.attach(*session);
        }
        if (toggle_3d) zbuffer_3d = !zbuffer_3d;
        if (auto* zb = dynamic_cast<ZBufferSession*>(session.get())) {
            if (a.depth_format) zb->set_format(*a.depth_format);
            if (a.depth_range) zb->set_range(*a.depth_range);
            bool edited = false;  // editing on the fat pixels
            if (a.move_screen_vertex) edited |= zb->move_vertex(a.move_screen_vertex->polygon, a.move_screen_vertex->vertex, a.move_screen_vertex->pixel);
            if (a.add_triangle) edited |= zb->add_triangle((*a.add_triangle)[0], (*a.add_triangle)[1], (*a.add_triangle)[2]);
            if (a.delete_polygon) edited |= zb->delete_polygon(*a.delete_polygon);
            if (a.undo) edited |= zb->undo();
            if (a.redo) edited |= zb->redo();
            if (edited) classroom.attach(*session);
            if (a.save_scene) save_edited(zb->edited_scene());
        }
        Session& p = *session;
        const bool may_move = a.toggle_play || a.step || a.step_back || a.micro_step || a.micro_step_back ||
                              a.to_start || a.to_end || a.seek || playback.playing;
        std::optional<ClipView> shown;
        const auto* clip = dynamic_cast<const ClipSession*>(session.get());
        if (animate && may_move && clip) shown = clip->view();  // cheap: the view's large parts are shared
        const std::size_t cursor = p.cursor();
        if (a.speed) playback.speed = *a.speed;
        if (a.toggle_play) playback.playing = !playback.playing && !p.at_end();
        if (a.step) p.step();
        if (a.step_back) p.step_back();
        if (a.micro_step) p.micro_step();
        if (a.micro_step_back) p.micro_step_back();
        if (a.to_start) p.seek(0);
        if (a.to_end) p.seek_end();
        if (a.seek) p.seek(*a.seek);
        if (a.step || a.step_back || a.micro_step || a.micro_step_back || a.to_start || a.to_end || a.seek)
            playback.playing = false;
        if (playback.playing) {
            playback.since_step += dt;
            if (playback.since_step >= 1.0 / playback.speed) {
                playback.since_step = 0;
                p.step();
                if (p.at_end()) playback.playing = false;
            }
        }
        // a step forward stops where a chapter pauses, so that its question is asked before the events answer it
        if (a.step || a.micro_step || playback.playing)
            if (const auto stop = classroom.first_pause_crossed(p, cursor)) {
                p.seek(*stop);
                playback.playing = false;
            }
        if (p.cursor() != cursor && shown) {  // a step was taken (either way): slide from what was shown
            before = std::move(shown);
            tween = 0;
        } else {
            tween = std::min(1.0, tween + dt / tween_seconds);
        }
    }
};

void keys(const SDL_Event& e, UiActions& a) {
    if (e.type != SDL_KEYDOWN) return;
    const bool shift = (e.key.keysym.mod & KMOD_SHIFT) != 0;
    switch (e.key.keysym.sym) {
        case SDLK_SPACE: a.toggle_play = true; break;
        case SDLK_RIGHT: (shift ? a.micro_step : a.step) = true; break;
        case SDLK_LEFT: (shift ? a.micro_step_back : a.step_back) = true; break;
        case SDLK_HOME: a.to_start = true; break;
        case SDLK_END: a.to_end = true; break;
        case SDLK_F5: a.reload = true; break;
        case SDLK_F1: a.toggle_keys = true; break;
        case SDLK_e: a.export_all = true; break;
        case SDLK_z:
            if (e.key.keysym.mod & KMOD_CTRL) (shift ? a.redo : a.undo) = true;
            break;
        case SDLK_y: if (e.key.keysym.mod & KMOD_CTRL) a.redo = true; break;
        case SDLK_s: a.save_scene = true; break;
        case SDLK_ESCAPE: a.close_overlays = true; break;
        case SDLK_PAGEDOWN: a.next_chapter = true; break;
        case SDLK_PAGEUP: a.previous_chapter = true; break;
        case SDLK_l: a.next_language = true; break;
        case SDLK_p: a.toggle_presets = true; break;
        case SDLK_r: a.toggle_report = true; break;
        case SDLK_LEFTBRACKET: a.column_narrower = true; break;
        case SDLK_RIGHTBRACKET: a.column_wider = true; break;
        case SDLK_b: a.back_to_lesson = true; break;
        case SDLK_0: a.digit = 0; break;
        default:  // 1 … 9: a question's choice; 3 alone: z-buffer fat pixels or 3D, portals plan or 3D, culling god's eye or camera
            if (e.key.keysym.sym >= SDLK_1 && e.key.keysym.sym <= SDLK_9) a.digit = int(e.key.keysym.sym - SDLK_0);
            break;
    }
}

// ── [SECTION] drawing a frame (draw) ────────────────────────────────────────────────────────────────────────
struct Renderer {
    LineBatches batches;
    std::vector<Label> labels;
    glm::mat4 view_projection{1};  // of the last frame's 3D view, for picking
    float view_w = 1, view_h = 1;   // its size in window points
};

// The 3D view's ray through a window point (x, y), hit with the plane z = 0: where a dragged 2D eye goes.
std::optional<glm::dvec3> on_floor_plan(const Renderer& r, float x, float y) {
    const glm::dmat4 inverse = glm::inverse(glm::dmat4(r.view_projection));
    const double nx = x / r.view_w * 2 - 1, ny = 1 - y / r.view_h * 2;
    const glm::dvec4 a = inverse * glm::dvec4(nx, ny, -1, 1), b = inverse * glm::dvec4(nx, ny, 1, 1);
    const glm::dvec3 from = glm::dvec3(a) / a.w, to = glm::dvec3(b) / b.w;
    if (std::abs(to.z - from.z) < 1e-12) return std::nullopt;
    const double t = -from.z / (to.z - from.z);
    return from + t * (to - from);
}

// The input vertex of a 2D BSP lesson within a few pixels of a window point (so a drag moves it), if any.
std::optional<std::pair<std::size_t, std::size_t>> vertex_near(const Renderer& r, const Session* s, float x, float y) {
    const auto* bsp = dynamic_cast<const BspSession*>(s);
    if (!bsp || !bsp->view().two_d) return std::nullopt;
    const auto& inputs = bsp->job().polygons;
    for (std::size_t i = 0; i < inputs.size(); ++i)
        for (std::size_t k = 0; k < inputs[i].vertices.size(); ++k) {
            const glm::vec4 c = r.view_projection * glm::vec4(glm::vec3(inputs[i].vertices[k]), 1);
            if (c.w <= 0) continue;
            const float sx = (c.x / c.w * 0.5f + 0.5f) * r.view_w, sy = (0.5f - c.y / c.w * 0.5f) * r.view_h;
            if (std::hypot(sx - x, sy - y) < 10) return std::pair{i, k};
        }
    return std::nullopt;
}

// Whether a window point is within a few pixels of the eye of a 2D BSP lesson (so a drag moves the eye).
bool near_the_eye(const Renderer& r, const Session* s, float x, float y) {
    const auto* bsp = dynamic_cast<const BspSession*>(s);
    if (!bsp || !bsp->view().two_d) return false;
    const glm::vec4 c = r.view_projection * glm::vec4(glm::vec3(bsp->view().eye), 1);
    if (c.w <= 0) return false;
    const float sx = (c.x / c.w * 0.5f + 0.5f) * r.view_w, sy = (0.5f - c.y / c.w * 0.5f) * r.view_h;
    return std::hypot(sx - x, sy - y) < 14;
}

// A world point of the 3D view as a window point (for scripted gestures given in world coordinates).
glm::vec2 window_point(const Renderer& r, const glm::dvec3& p) {
    const glm::vec4 c = r.view_projection * glm::vec4(glm::vec3(p), 1);
    return {(c.x / c.w * 0.5f + 0.5f) * r.view_w, (0.5f - c.y / c.w * 0.5f) * r.view_h};
}

// The input segment of a 2D BSP lesson within a few pixels of a window point (right-click deletes it), if any.
std::optional<std::size_t> segment_near(const Renderer& r, const Session* s, float x, float y) {
    const auto* bsp = dynamic_cast<const BspSession*>(s);
    if (!bsp || !bsp->view().two_d) return std::nullopt;
    const auto& inputs = bsp->job().polygons;
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        if (inputs[i].vertices.size() != 2) continue;
        const glm::vec2 a = window_point(r, inputs[i].vertices[0]), b = window_point(r, inputs[i].vertices[1]), p(x, y);
        const glm::vec2 ab = b - a;
        const float t = glm::dot(ab, ab) > 0 ? std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.f, 1.f) : 0.f;
        if (glm::length(p - (a + t * ab)) < 8) return i;
    }
    return std::nullopt;
}

// The z-buffer lesson's frame-buffer grid as the canvas draws it, or nullopt when none is shown (3D, an overlay).
std::optional<FatGrid> fat_grid(const Lessonplay& lp, const ImGuiIO& io) {
    const auto* zb = dynamic_cast<const ZBufferSession*>(lp.session.get());
    if (!zb || lp.zbuffer_3d || lp.show_presets || lp.show_keys || lp.show_report) return std::nullopt;
    const PanelLayout l{io.DisplaySize.x, io.DisplaySize.y, clamp_side(lp.side, io.DisplaySize.x)};
    return zbuffer_frame_grid(*zb, 0, 0, l.width - l.side, l.height - l.bottom);
}

// The scene vertex of a z-buffer lesson within a few points of a window point, as (polygon, vertex).
std::optional<std::pair<std::size_t, std::size_t>> screen_vertex_near(const ZBufferSession& zb, const FatGrid& g, float x, float y) {
    const auto& polygons = zb.edited_scene().polygons;
    for (std::size_t i = 0; i < polygons.size(); ++i)
        for (std::size_t k = 0; k < polygons[i].vertices.size(); ++k)
            if (const auto s = zb.on_screen(polygons[i].vertices[k]))
                if (std::hypot(g.x0 + float(s->x) * g.cell - x, g.y0 + float(s->y) * g.cell - y) < 10) return std::pair{i, k};
    return std::nullopt;
}

// F1: every key, over the view.
void keys_panel(const PanelLayout& l) {
    static constexpr std::pair<const char*, const char*> rows[] = {
        {"Space", "play / pause"},          {"→  ←", "one Step forward / back"},
        {"Shift+→  Shift+←", "one event (micro-step)"}, {"Home  End", "first / last step"},
        {"PageDown  PageUp", "next / previous chapter"}, {"1 … 9", "answer a question"},
        {"L", "narration language"},       {"P", "presets: extreme cases, a random scene (0), back (B)"},
        {"R", "error against run time for this algorithm's family"},       {"3", "3D view / camera view / floor plan"},
        {"F5", "reload the lesson (edits reload by themselves)"}, {"E", "export PNG, trace and scene to hsrviz-export/"},
        {"Ctrl+Z  Ctrl+Y  S", "undo, redo, save an edited 2D scene"}, {"F1  Esc", "show / hide these keys"}, {"[  ]", "panel column narrower / wider (remembered)"},
        {"drag, wheel", "orbit and zoom the 3D view; drag an eye or a segment's end in 2D"},
        {"Shift+drag, right-click", "2D scenes: a new segment; z-buffer pixels: a new triangle; delete what is clicked"},
    };
    ImGui::SetNextWindowPos(ImVec2((l.width - l.side) / 2, (l.height - l.bottom) / 2), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::Begin("Keys", nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings);
    if (ImGui::BeginTable("keys", 2)) {
        for (const auto& [k, what] : rows) {
            ImGui::TableNextColumn();
            ImGui::TextColored(ImVec4(0.94f, 0.89f, 0.26f, 1), "%s", k);
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(what);
        }
        ImGui::EndTable();
    }
    ImGui::End();
}

// `layout` is in ImGui's units (window points); `scale` turns them into framebuffer pixels (2 on a HiDPI display).
void draw_frame(const Lessonplay& lp, Renderer& r, const PanelLayout& layout, float scale, UiActions& actions) {
    const float view_w = layout.width - layout.side, view_h = layout.height - layout.bottom;
    const auto px = [&](float points) { return GLsizei(points * scale); };
    glViewport(0, 0, px(layout.width), px(layout.height));
    glClearColor(palette::background.x, palette::background.y, palette::background.z, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (!lp.session) {
        error_panel(lp.error + (lp.path != lp.home ? "\n\nB: back to the lesson.  P: the other presets." : ""), layout, actions);
        if (lp.show_presets) preset_panel(lp.presets, false, lp.next_seed, lp.path != lp.home, layout, actions);
        return;
    }
    const Session& s = *lp.session;
    r.batches.faint.clear();
    r.batches.bold.clear();
    r.labels.clear();
    std::string detail;
    const auto* clip = dynamic_cast<const ClipSession*>(&s);
    const auto* bsp = dynamic_cast<const BspSession*>(&s);
    const auto* cull = dynamic_cast<const CullSession*>(&s);
    const auto* zb = dynamic_cast<const ZBufferSession*>(&s);
    const auto* ray = dynamic_cast<const RayCastSession*>(&s);
    const auto* scan = dynamic_cast<const ScanLineSession*>(&s);
    const auto* merge = dynamic_cast<const ZMergeSession*>(&s);
    const auto* sort = dynamic_cast<const DepthSortSession*>(&s);
    const auto* pvs = dynamic_cast<const PvsSession*>(&s);
    const auto* portals = dynamic_cast<const PortalRenderSession*>(&s);
    if (portals && lp.zbuffer_3d) draw_portal_view(portals->view(), r.batches, r.labels);
    if (pvs || portals) detail = "cells and portals · plan (x, y) is the world's (x, -z)";
    const auto* culling = dynamic_cast<const CullingLesson*>(&s);
    if (culling) {
        draw_culling_view(culling->culling_view(), r.batches, r.labels);
        detail = std::to_string(culling->culling_view().world->scene.polygons.size()) + " primitives · " +
                 (culling->culling_view().world->hierarchy.kind == algo::HierarchyKind::bvh ? "BVH" : "octree") +
                 (lp.zbuffer_3d ? " · from the camera" : " · god's-eye view");
    }
    if (sort) {
        draw_depth_sort_view(sort->view(), r.batches, r.labels);
        detail = "in the canonical view volume (x, y, z in [-1, 1]) · the eye far along -z";
    }
    if (merge)
        detail = std::to_string(merge->lesson().grid.width) + "×" + std::to_string(merge->lesson().grid.height) +
                 " pixels · " + std::string(algo::to_string(merge->lesson().depth_format));
    if (scan)
        detail = std::to_string(scan->lesson().grid.width) + "×" + std::to_string(scan->lesson().grid.height) +
                 " pixels · one-line z-buffer, " + std::string(algo::to_string(scan->lesson().depth_format));
    if (ray) {
        draw_raycast_view(ray->view(), ray->scene(), r.batches, r.labels);
        detail = std::to_string(ray->lesson().grid.width) + "×" + std::to_string(ray->lesson().grid.height) +
                 " rays · double precision · " + std::string(algo::to_string(ray->view().acceleration));
    }
    if (zb && lp.zbuffer_3d) draw_zbuffer_3d(zb->view(), zb->lesson().scene, r.batches, r.labels);
    if (zb)
        detail = std::to_string(zb->lesson().grid.width) + "×" + std::to_string(zb->lesson().grid.height) +
                 " pixels · " + std::string(algo::to_string(zb->format())) + " · top-left rule";
    if (cull) {
        draw_cull_view(cull->view(), s.lesson().scene, r.batches, r.labels);
        detail = std::string(algo::to_string(cull->view().test)) + " test · eye at the scene camera";
    }
    if (clip) {
        draw_clip_view(clip->view(), s.lesson().scene, r.batches, r.labels,
                       {lp.before ? &*lp.before : nullptr, float(lp.tween)});
        detail = clip->space() == algo::ClipSpace::homogeneous ? "clip space −w ≤ x, y, z ≤ w and w ≥ ε = 1e-9"
                                                               : "the canonical cube −1 ≤ x, y, z ≤ 1";
    }
    if (bsp) {
        draw_bsp_view(bsp->view(), bsp->edited_scene(), r.batches, r.labels);  // edits add segments: their colours
        detail = "splitter: " + std::string(algo::to_string(bsp->stats().rule)) + " · ε = 1e-9 × extent" +
                 (bsp->view().two_d ? " · 2D" : "");
    }
    // the 3D view fills the space left of the panels and above the timeline (GL's y axis points up)
    glViewport(0, px(layout.bottom), px(view_w), px(view_h));
    glm::mat4 vp = lp.camera.view_projection(view_w / view_h);
    if (culling && lp.zbuffer_3d) {  // key 3 in a culling lesson: the view from the scene's own camera
        algo::Camera eye = culling->culling_view().world->scene.camera;
        eye.aspect = view_w / view_h;
        vp = glm::mat4(algo::view_projection(eye));
    }
    r.view_projection = vp;
    r.view_w = view_w;
    r.view_h = view_h;
    r.batches.faint.draw(vp, 1.5f * scale, 7.0f * scale);
    r.batches.bold.draw(vp, 3.5f * scale, 11.0f * scale);
    glViewport(0, 0, px(layout.width), px(layout.height));

    draw_labels(r.labels, vp, 0, 0, view_w, view_h);
    if (zb && !lp.zbuffer_3d) zbuffer_canvas(*zb, 0, 0, view_w, view_h);
    if (ray) raycast_image(*ray, 0, 0, view_w, view_h);
    if (scan) scanline_canvas(*scan, 0, 0, view_w, view_h);
    if (merge) zmerge_canvas(*merge, 0, 0, view_w, view_h);
    if (sort) depth_sort_canvas(*sort, 0, 0, view_w, view_h, lp.animate);
    if (pvs || (portals && !lp.zbuffer_3d)) portal_plan_canvas(s, 0, 0, view_w, view_h, actions);
    if (culling) culling_canvas(*culling, 0, 0, view_w, view_h);
    if (s.lesson().chapters.empty()) lesson_panel(s, detail, layout);
    else chapter_lesson_panel(s, lp.classroom, detail, layout);
    pseudocode_panel(s, layout);
    if (clip) clip_state_panel(*clip, layout);
    if (bsp) bsp_state_panel(*bsp, layout);
    if (cull) cull_state_panel(*cull, layout);
    if (zb) zbuffer_state_panel(*zb, lp.zbuffer_3d, layout, actions);
    if (ray) raycast_state_panel(*ray, layout);
    if (scan) scanline_state_panel(*scan, layout);
    if (merge) zmerge_state_panel(*merge, layout);
    if (sort) depth_sort_state_panel(*sort, layout);
    if (pvs) pvs_state_panel(*pvs, layout);
    if (culling) culling_state_panel(*culling, layout);
    if (portals) portal_state_panel(*portals, lp.zbuffer_3d, layout, actions);
    question_panel(s, lp.classroom, 0, 0, view_w, view_h, actions);
    if (lp.show_report) report_panel(lp.report, layout);
    if (lp.show_keys) keys_panel(layout);
    if (lp.show_presets && lp.session)
        preset_panel(lp.presets, has_random_scene(lp.session->lesson().algorithm), lp.next_seed,
                     lp.path != lp.home, layout, actions);
    narration_panel(s, layout);
    timeline_panel(s, lp.playback, layout, actions);
}

// The window's pixels at half size (each 2×2 block averaged), RGBA, the top row first.
std::vector<unsigned char> half_size_pixels(int w, int h) {
    std::vector<unsigned char> full(std::size_t(w) * std::size_t(h) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, full.data());
    const int hw = w / 2, hh = h / 2;
    std::vector<unsigned char> half(std::size_t(hw) * std::size_t(hh) * 4);
    for (int y = 0; y < hh; ++y)
        for (int x = 0; x < hw; ++x)
            for (int c = 0; c < 4; ++c) {
                int sum = 0;
                for (int dy = 0; dy < 2; ++dy)
                    for (int dx = 0; dx < 2; ++dx)  // GL's rows run bottom up: flip while shrinking
                        sum += full[(std::size_t(h - 1 - (2 * y + dy)) * std::size_t(w) + std::size_t(2 * x + dx)) * 4 + std::size_t(c)];
                half[(std::size_t(y) * std::size_t(hw) + std::size_t(x)) * 4 + std::size_t(c)] = static_cast<unsigned char>(sum / 4);
            }
    return half;
}

bool write_png(const std::string& path, int w, int h) {
    std::vector<unsigned char> pixels(std::size_t(w) * std::size_t(h) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    stbi_flip_vertically_on_write(1);
    return stbi_write_png(path.c_str(), w, h, 4, pixels.data(), w * 4) != 0;
}

// E: the window as a PNG, the lesson's trace, and its scene as TOML, into hsrviz-export/.
void export_lesson(const Session& s, const std::string& path, const std::optional<std::string>& algorithm, int width, int height) {
    const std::string dir = "hsrviz-export", stem = std::filesystem::path(s.lesson().source).stem().string();
    std::filesystem::create_directories(dir);
    const std::string png = dir + "/" + stem + "-step-" + std::to_string(s.cursor()) + ".png";
    const std::string trace = dir + "/" + stem + ".jsonl", scene = dir + "/" + stem + "-scene.toml";
    const bool ok = write_png(png, width, height) && run_trace({path, trace, algorithm}) == 0 &&
                    static_cast<bool>(std::ofstream(scene) << algo::scene_toml(s.lesson().scene));
    std::printf("hsrviz: %s %s, %s and %s\n", ok ? "exported" : "could not export all of", png.c_str(), trace.c_str(), scene.c_str());
}

// ── [SECTION] window, GL context and ImGui setup ────────────────────────────────────────────────────────────
void load_fonts(ImGuiIO& io, float scale) {
    // Latin, Greek (ε), punctuation, arrows and maths (≤ ≥ → −): the characters our sentences use.
    static const ImWchar ranges[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2000, 0x206F, 0x2190, 0x21FF,
                                     0x2200, 0x22FF, 0x25A0, 0x25FF, 0};
    const char* sans = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
    const char* mono = "/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf";
    if (!std::filesystem::exists(sans) || !std::filesystem::exists(mono)) {
        io.Fonts->AddFontDefault();  // ASCII only: ≤, → and ε will show as '?'
        return;
    }
    io.Fonts->AddFontFromFileTTF(sans, 17.0f * scale, nullptr, ranges);
    io.Fonts->AddFontFromFileTTF(mono, 15.0f * scale, nullptr, ranges);  // pseudocode
}

// A window a person works in, not one a command line scripts (screenshots, recordings, GIFs keep their size).
bool interactive(const AppOptions& o) { return !o.screenshot && !o.record_dir && !o.gif; }

struct Window {
    SDL_Window* window = nullptr;
    SDL_GLContext gl = nullptr;
    WindowSettings settings;  // as the last run left them

    bool open(const AppOptions& o) {
        if (SDL_Init(SDL_INIT_VIDEO | SDL_INIT_TIMER) != 0) {
            std::fprintf(stderr, "hsrviz: SDL_Init failed: %s\n", SDL_GetError());
            return false;
        }
        SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_CORE);
        SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 3);
        SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 3);
        SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
        SDL_GL_SetAttribute(SDL_GL_DEPTH_SIZE, 24);
        // An interactive window opens as the last one closed (unless --size says otherwise); scripted ones at their size
        const bool remembered = interactive(o) && !o.size_given && !o.projector;
        const int width = remembered ? settings.width : o.width, height = remembered ? settings.height : o.height;
        const int x = remembered && settings.x ? *settings.x : int(SDL_WINDOWPOS_CENTERED);
        const int y = remembered && settings.y ? *settings.y : int(SDL_WINDOWPOS_CENTERED);
        window = SDL_CreateWindow("hsrviz", x, y, width, height,
                                  SDL_WINDOW_OPENGL | SDL_WINDOW_RESIZABLE | SDL_WINDOW_ALLOW_HIGHDPI |
                                      (remembered && settings.maximized ? SDL_WINDOW_MAXIMIZED : 0) |
                                      (o.projector && !o.screenshot && !o.record_dir ? SDL_WINDOW_FULLSCREEN_DESKTOP : 0));  // screenshots keep their size
        if (!window) {
            std::fprintf(stderr, "hsrviz: cannot open a window: %s\n", SDL_GetError());
            return false;
        }
        gl = SDL_GL_CreateContext(window);
        if (!gl) {
            std::fprintf(stderr, "hsrviz: cannot create an OpenGL 3.3 context: %s\n", SDL_GetError());
            return false;
        }
        SDL_GL_MakeCurrent(window, gl);
        SDL_GL_SetSwapInterval(1);
        return true;
    }
    void close() {
        if (gl) SDL_GL_DeleteContext(gl);
        if (window) SDL_DestroyWindow(window);
        SDL_Quit();
    }
};

}  // namespace

// ── [SECTION] the loop ──────────────────────────────────────────────────────────────────────────────────────
int run_app(const AppOptions& o) {
    Window w;
    std::string warning;
    const std::string settings_path = window_settings_path();
    WindowSettings settings = read_window_settings(settings_path, warning);
    if (!warning.empty()) std::fprintf(stderr, "hsrviz: %s\n", warning.c_str());
    w.settings = settings;
    if (!w.open(o)) {
        w.close();
        return 1;
    }
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    ImGui::StyleColorsDark();
    ImGui::GetStyle().WindowRounding = 0;
    load_fonts(io, o.projector ? 1.3f : 1.0f);
    if (o.projector) {  // high contrast for a washed-out projector: white on black, bright frames
        ImGuiStyle& style = ImGui::GetStyle();
        style.Colors[ImGuiCol_Text] = ImVec4(1, 1, 1, 1);
        style.Colors[ImGuiCol_WindowBg] = ImVec4(0, 0, 0, 1);
        style.Colors[ImGuiCol_Border] = ImVec4(0.8f, 0.8f, 0.8f, 1);
        style.FrameBorderSize = 1, style.WindowBorderSize = 2;
    }
    ImGui_ImplSDL2_InitForOpenGL(w.window, w.gl);
    ImGui_ImplOpenGL3_Init("#version 330 core");

    int exit_code = 0;
    {
        Lessonplay lp;
        lp.load(o);
        lp.side = settings.side;
        for (int k = 0; k < 8 && !settings.language.empty() && lp.classroom.language() != settings.language; ++k)
            lp.classroom.next_language();  // the language last chosen, where the lesson has it
        lp.playback.playing = o.autoplay;
        lp.animate = !o.screenshot && !o.record_dir && !o.gif;
        std::optional<GifWriter> gif;  // half the drawable's size (made at the first frame): enough for slides
        bool gif_failed = false;
        if (o.gif && lp.session) lp.session->seek(std::min(o.gif_from, lp.session->known()));
        Renderer renderer;
        std::uint64_t frame = 0, last_ticks = SDL_GetTicks64();
        bool dragging = false, dragging_eye = false, running = true;
        std::int64_t dragging_input = -1;  // the vertex of a 2D scene being dragged: its input (−1: none) …
        std::size_t dragging_corner = 0;   // … and which of its vertices
        std::optional<glm::dvec3> drawing_from;  // Shift+drag in a 2D scene: where the new segment starts
        // the fat pixels of a z-buffer lesson: the vertex being dragged (polygon, vertex), or where a Shift+drag began
        bool screen_dragging = false, screen_drawing = false;
        std::pair<std::size_t, std::size_t> screen_vertex{0, 0};
        glm::dvec2 screen_drawing_from(0);
        if (o.record_dir) std::filesystem::create_directories(*o.record_dir);

        std::size_t next_key = 0;
        std::vector<double> frame_ms;  // --frame-log
        std::uint64_t frame_start = SDL_GetPerformanceCounter();
        while (running) {
            UiActions actions;
            SDL_Event e;
            bool scripted_shift = false;
            if (frame > 0 && next_key < o.keys.size()) {  // scripted input goes through the same queue as real input
                const auto input = parse_scripted_input(o.keys[next_key]);
                if (!input) {
                    std::fprintf(stderr, "hsrviz: --keys: unknown key or gesture \"%s\"\n", o.keys[next_key].c_str());
                    exit_code = 2;
                    break;
                }
                if (input->kind == ScriptedInput::Kind::key) {
                    key_event(input->key, e);
                    SDL_PushEvent(&e);
                } else {
                    // the fat-pixel view takes grid pixels; every other view the scene's plane z = 0
                    const auto grid = fat_grid(lp, io);
                    const auto to_window = [&](glm::dvec2 p) {
                        return grid ? glm::vec2(grid->x0 + float(p.x) * grid->cell, grid->y0 + float(p.y) * grid->cell)
                                    : window_point(renderer, {p, 0.0});
                    };
                    const glm::vec2 a = to_window(input->from), b = to_window(input->to);
                    const auto ax = int(std::lround(a.x)), ay = int(std::lround(a.y)), bx = int(std::lround(b.x)), by = int(std::lround(b.y));
                    const bool right = input->kind == ScriptedInput::Kind::right_click;
                    scripted_shift = input->kind == ScriptedInput::Kind::shift_drag;
                    if (scripted_shift) SDL_SetModState(KMOD_LSHIFT);
                    for (SDL_Event m : {mouse_motion_event(ax, ay, 0, 0, false), mouse_button_event(true, right ? SDL_BUTTON_RIGHT : SDL_BUTTON_LEFT, ax, ay),
                                        mouse_motion_event(bx, by, bx - ax, by - ay, !right),
                                        mouse_button_event(false, right ? SDL_BUTTON_RIGHT : SDL_BUTTON_LEFT, bx, by)})
                        SDL_PushEvent(&m);
                }
                ++next_key;
            }
            while (SDL_PollEvent(&e)) {
                ImGui_ImplSDL2_ProcessEvent(&e);
                if (e.type == SDL_QUIT) running = false;
                if (!io.WantCaptureKeyboard) keys(e, actions);
                // the z-buffer's fat pixels (an ImGui canvas, so before the capture test): drag a vertex, Shift+drag
                // a new triangle, right-click a polygon away
                if (const auto grid = fat_grid(lp, io)) {
                    const auto& zb = dynamic_cast<const ZBufferSession&>(*lp.session);
                    const auto pixel = [&](int x, int y) { return glm::dvec2((float(x) - grid->x0) / grid->cell, (float(y) - grid->y0) / grid->cell); };
                    const auto on_grid = [&](glm::dvec2 p) { return p.x >= 0 && p.y >= 0 && p.x < zb.lesson().grid.width && p.y < zb.lesson().grid.height; };
                    if (e.type == SDL_MOUSEBUTTONDOWN && e.button.button == SDL_BUTTON_LEFT) {
                        const auto near = screen_vertex_near(zb, *grid, float(e.button.x), float(e.button.y));
                        screen_dragging = near.has_value();
                        if (near) screen_vertex = *near;
                        screen_drawing = !screen_dragging && (SDL_GetModState() & KMOD_SHIFT) && on_grid(pixel(e.button.x, e.button.y));
                        screen_drawing_from = pixel(e.button.x, e.button.y);
                    }
                    if (e.type == SDL_MOUSEMOTION && screen_dragging)
                        actions.move_screen_vertex = UiActions::ScreenVertexMove{screen_vertex.first, screen_vertex.second, pixel(e.motion.x, e.motion.y)};
                    if (e.type == SDL_MOUSEBUTTONUP && e.button.button == SDL_BUTTON_LEFT && screen_drawing) {
                        const glm::dvec2 to = pixel(e.button.x, e.button.y);
                        actions.add_triangle = std::array{screen_drawing_from, glm::dvec2(to.x, screen_drawing_from.y), to};
                    }
                    if (e.type == SDL_MOUSEBUTTONDOWN && e.button.button == SDL_BUTTON_RIGHT) {
                        const glm::dvec2 p = pixel(e.button.x, e.button.y);
                        if (on_grid(p)) {
                            const std::int32_t owner = zb.view().owner[std::size_t(int(p.y)) * std::size_t(zb.lesson().grid.width) + std::size_t(int(p.x))];
                            if (owner >= 0) actions.delete_polygon = std::size_t(owner);
                        }
                    }
                    if (e.type == SDL_MOUSEBUTTONUP) screen_dragging = screen_drawing = false;
                }
                if (!io.WantCaptureMouse) {  // drag the eye of a 2D lesson, or orbit and zoom the 3D view
                    if (e.type == SDL_MOUSEBUTTONDOWN && e.button.button == SDL_BUTTON_LEFT) {
                        const float x = float(e.button.x), y = float(e.button.y);
                        dragging_eye = near_the_eye(renderer, lp.session.get(), x, y);
                        const auto v = dragging_eye ? std::nullopt : vertex_near(renderer, lp.session.get(), x, y);
                        dragging_input = v ? std::int64_t(v->first) : -1, dragging_corner = v ? v->second : 0;
                        // Shift+drag on empty ground of a 2D scene draws a new segment; otherwise a drag orbits
                        const auto* bsp = dynamic_cast<const BspSession*>(lp.session.get());
                        drawing_from.reset();
                        if (!dragging_eye && dragging_input < 0 && (SDL_GetModState() & KMOD_SHIFT) && bsp && bsp->view().two_d)
                            drawing_from = on_floor_plan(renderer, x, y);
                        dragging = !dragging_eye && dragging_input < 0 && !drawing_from;
                    }
                    if (e.type == SDL_MOUSEBUTTONDOWN && e.button.button == SDL_BUTTON_RIGHT)
                        actions.delete_input = segment_near(renderer, lp.session.get(), float(e.button.x), float(e.button.y));
                    if (e.type == SDL_MOUSEBUTTONUP && e.button.button == SDL_BUTTON_LEFT && drawing_from)
                        if (const auto to = on_floor_plan(renderer, float(e.button.x), float(e.button.y)))
                            actions.add_segment = std::pair{*drawing_from, *to};
                    if (e.type == SDL_MOUSEWHEEL) lp.camera.zoom(float(e.wheel.y));
                }
                if (e.type == SDL_MOUSEBUTTONUP) dragging = dragging_eye = false, dragging_input = -1, drawing_from.reset();
                if (e.type == SDL_MOUSEMOTION && dragging_input >= 0)
                    if (const auto at = on_floor_plan(renderer, float(e.motion.x), float(e.motion.y)))
                        actions.move_vertex = UiActions::VertexMove{std::size_t(dragging_input), dragging_corner, *at};
                if (e.type == SDL_MOUSEMOTION && dragging) lp.camera.orbit(float(e.motion.xrel), float(e.motion.yrel));
                if (e.type == SDL_MOUSEMOTION && dragging_eye)
                    actions.move_eye = on_floor_plan(renderer, float(e.motion.x), float(e.motion.y));
            }
            if (scripted_shift) SDL_SetModState(KMOD_NONE);
            const std::uint64_t ticks = SDL_GetTicks64();
            // recording and screenshots take one Step per frame, so the same command gives the same picture
            if ((o.record_dir || o.gif || (o.screenshot && o.keys.empty())) && frame > 0) actions.step = true;
            lp.update(actions, double(ticks - last_ticks) / 1000.0, o);
            last_ticks = ticks;

            ImGui_ImplOpenGL3_NewFrame();
            ImGui_ImplSDL2_NewFrame();
            ImGui::NewFrame();
            int width = 0, height = 0;
            SDL_GL_GetDrawableSize(w.window, &width, &height);
            UiActions from_panels;
            lp.side = clamp_side(lp.side, io.DisplaySize.x);
            draw_frame(lp, renderer, PanelLayout{io.DisplaySize.x, io.DisplaySize.y, lp.side}, io.DisplayFramebufferScale.x,
                       from_panels);
            ImGui::Render();
            ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
            ++frame;

            if (o.record_dir) {
                char name[64];
                std::snprintf(name, sizeof name, "/frame_%04llu.png", static_cast<unsigned long long>(frame - 1));
                write_png(*o.record_dir + name, width, height);
                const bool done = !lp.session || lp.session->at_end() || frame >= 2000;
                if (done) running = false;
            }
            if (lp.export_pending && lp.session) {
                lp.export_pending = false;
                export_lesson(*lp.session, lp.path, lp.algorithm, width, height);
            }
            if (o.gif) {
                if (!gif && !gif_failed) {
                    gif.emplace(*o.gif, width / 2, height / 2, 50);
                    if (!gif->ok()) std::fprintf(stderr, "hsrviz: cannot write %s\n", o.gif->c_str()), gif.reset(), gif_failed = true, exit_code = 1;
                }
                if (gif) gif->add_frame(half_size_pixels(width, height));
                if (!gif || !lp.session || lp.session->at_end() || lp.session->cursor() >= o.gif_to) running = false;
            }
            if (o.screenshot && frame >= std::uint64_t(o.frames)) {
                if (lp.session)
                    std::printf("hsrviz: at step %zu of %zu%s, %s\n", lp.session->cursor(), lp.session->known(),
                                lp.session->complete() ? "" : "+",
                                lp.playback.playing ? "playing" : "paused");
                if (lp.session && lp.classroom.questions() > 0)
                    std::printf("hsrviz: score %d of %d answered, %d questions, language %s\n", lp.classroom.right(),
                                lp.classroom.answered(), lp.classroom.questions(), lp.classroom.language().c_str());
                if (!write_png(*o.screenshot, width, height)) {
                    std::fprintf(stderr, "hsrviz: cannot write %s\n", o.screenshot->c_str());
                    exit_code = 1;
                }
                running = false;
            }
            SDL_GL_SwapWindow(w.window);
            if (o.frame_log) {  // from the start of one frame to the start of the next
                const std::uint64_t now = SDL_GetPerformanceCounter();
                frame_ms.push_back(1000.0 * double(now - frame_start) / double(SDL_GetPerformanceFrequency()));
                frame_start = now;
            }
            // carry the panels' requests into the next update
            if (from_panels.toggle_play || from_panels.step || from_panels.step_back || from_panels.micro_step ||
                from_panels.micro_step_back || from_panels.to_start || from_panels.to_end || from_panels.seek ||
                from_panels.speed || from_panels.reload || from_panels.move_eye || from_panels.preset || from_panels.random_scene ||
                from_panels.back_to_lesson)
                lp.update(from_panels, 0, o);
        }
        if (o.frame_log && !frame_ms.empty()) {
            std::ofstream log(*o.frame_log);
            for (double ms : frame_ms) log << ms << '\n';
            std::vector<double> sorted = frame_ms;
            std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(sorted.size() / 2), sorted.end());
            std::printf("hsrviz: %zu frames, median %.2f ms, written to %s\n", frame_ms.size(), sorted[sorted.size() / 2], o.frame_log->c_str());
        }
        if (gif) {
            const int frames = gif->frames();
            if (!gif->close()) exit_code = 1;
            std::printf("hsrviz: wrote %d frames to %s\n", frames, o.gif->c_str());
        }
        if (o.gif && !lp.session) exit_code = 1;
        if (o.record_dir) {
            std::printf("hsrviz: wrote %llu frames to %s/frame_*.png\n", static_cast<unsigned long long>(frame),
                        o.record_dir->c_str());
            if (!lp.session) exit_code = 1;
        }
        // Remember the layout: the column and the language always, the window's size and place when a person sized it
        WindowSettings keep = settings;
        keep.side = lp.side;
        keep.language = lp.classroom.language();
        if (interactive(o) && !o.projector) {
            const Uint32 flags = SDL_GetWindowFlags(w.window);
            keep.maximized = (flags & SDL_WINDOW_MAXIMIZED) != 0;
            if (!keep.maximized && !(flags & SDL_WINDOW_FULLSCREEN)) {
                int x = 0, y = 0;
                SDL_GetWindowSize(w.window, &keep.width, &keep.height);
                SDL_GetWindowPosition(w.window, &x, &y);
                keep.x = x, keep.y = y;
            }
        }
        if (keep != settings && !write_window_settings(settings_path, keep))
            std::fprintf(stderr, "hsrviz: cannot write %s\n", settings_path.c_str());
    }
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplSDL2_Shutdown();
    ImGui::DestroyContext();
    w.close();
    return exit_code;
}

}  // namespace hsr::viz
