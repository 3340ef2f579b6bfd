// SPDX-License-Identifier: MIT
// libFuzzer: any text as a lesson or scene file, played in the window's panels with no window and no GL. The file is
// loaded as the window loads it (LessonPlay::load: its error is shown instead when it fails), then a few frames are
// drawn, each one stepping on: the family's 3D view filled (its line batches and labels), every panel drawn through
// Dear ImGui (the same draw_frame_panels the window calls), the frame ended with ImGui::Render. A crash, a sanitizer
// report, or draw data the GL backend would read past (an index beyond its vertices, a command beyond its indices)
// is a finding.
//
// Input: byte 0 picks the algorithm (bits 0–4: one of the registry's, or the file's own past the end) and the
// overlays (bit 5 keys, bit 6 presets, bit 7 the lesson menu); byte 1 the frames (bits 0–2: 1 to 8), the second view
// (bit 3), a jump to the end on the last frame (bit 4), the next chapter (bit 5) and the next language (bit 6); the
// rest is the file.
#include <imgui.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "frame_panels.h"
#include "lesson_play.h"
#include "panels/layout_audit.h"
#include "registry.h"
#include "screens/screens.h"
#include "window.h"

using namespace hsr::viz;

namespace {

void start_imgui() {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(1280, 800);
    io.DeltaTime = 1.0f / 60;
    io.BackendFlags |= ImGuiBackendFlags_RendererHasVtxOffset;  // as the OpenGL 3 backend says it can
    ImGui::StyleColorsDark();
    load_fonts(io, 1.0f);
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);  // the atlas built, as the backend's texture would be
}

// What the OpenGL 3 backend reads: every command's indices within the list, every index within the vertices.
void check_draw_data() {
    const ImDrawData* data = ImGui::GetDrawData();
    if (!data || !data->Valid) std::abort();
    for (int l = 0; l < data->CmdListsCount; ++l) {
        const ImDrawList* list = data->CmdLists[l];
        for (const ImDrawCmd& cmd : list->CmdBuffer) {
            if (cmd.UserCallback) continue;
            if (cmd.IdxOffset + cmd.ElemCount > unsigned(list->IdxBuffer.Size)) std::abort();
            for (unsigned i = cmd.IdxOffset; i < cmd.IdxOffset + cmd.ElemCount; ++i)
                if (cmd.VtxOffset + list->IdxBuffer[int(i)] >= unsigned(list->VtxBuffer.Size)) std::abort();
        }
    }
}

// The file is played from TMP/hsrviz-fuzz-panels-PID/lessons/, beside a link to the source tree's assets/, so that a
// shipped lesson's `scene = "../assets/scenes/…"` (the seeds) finds its scene as it does in lessons/.
std::string lesson_path() {
    namespace fs = std::filesystem;
    const fs::path root = fs::temp_directory_path() / ("hsrviz-fuzz-panels-" + std::to_string(getpid()));
    fs::create_directories(root / "lessons");
    std::error_code ec;
    fs::create_directory_symlink(HSR_SOURCE_DIR "/assets", root / "assets", ec);  // there already: fine
    return (root / "lessons" / "fuzz.toml").string();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const bool started = (start_imgui(), true);
    (void)started;
    if (size < 2) return 0;
    static const std::string path = lesson_path();
    {
        std::ofstream file(path, std::ios::binary | std::ios::trunc);
        file.write(reinterpret_cast<const char*>(data + 2), std::streamsize(size - 2));
    }
    const auto all = hsr::algo::algorithms();
    AppOptions o;
    o.lesson_path = path;
    if (const std::size_t pick = data[0] & 31u; pick < all.size()) o.algorithm = std::string(all[pick].id);
    LessonPlay lp;
    lp.animate = false;
    lp.load(o);
    lp.show_keys = data[0] & 32u, lp.show_presets = data[0] & 64u, lp.show_menu = data[0] & 128u;
    lp.second_view = data[1] & 8u;
    const int frames = 1 + (data[1] & 7);
    for (int frame = 0; frame < frames; ++frame) {
        UiActions a;
        a.step = frame > 0;
        a.to_end = frame == frames - 1 && (data[1] & 16u);
        a.next_chapter = frame == 1 && (data[1] & 32u);
        a.next_language = frame == 1 && (data[1] & 64u);
        lp.update(a, 1.0 / 60, o);

        ImGui::NewFrame();
        layout_problems().clear();
        LineBatches lines;  // filled, never drawn: no GL here
        std::vector<Label> labels;
        UiActions from_panels;
        draw_frame_content(lp, lines, labels, arrange_frame(lp, 1280, 800), from_panels);
        ImGui::Render();
        check_draw_data();
    }
    return 0;
}
