// SPDX-License-Identifier: MIT
#include "panels/culling_panels.h"

#include <algorithm>
#include <cstdio>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include <imgui.h>

#include "panels/panel_style.h"
#include "panels/state_legend.h"
#include "panels/wrapped_text.h"
#include "state/strings.h"

namespace hsr::viz {
namespace {

// A stage's name as the student reads it (the command line's names are algo::to_string's)
std::string stage_name(algo::Stage s) {
    switch (s) {
        case algo::Stage::back_face: return tr("culling.stage_back_face");
        case algo::Stage::frustum: return tr("culling.stage_frustum");
        case algo::Stage::detail: return tr("culling.stage_detail");
        case algo::Stage::occluders: return tr("culling.stage_occluders");
        case algo::Stage::portals: return tr("culling.stage_portals");
        case algo::Stage::hiz: return tr("culling.stage_hiz");
        case algo::Stage::hse: return tr("culling.stage_hse");
    }
    return "?";
}

std::string machine_name(algo::CullingMachine m) {
    switch (m) {
        case algo::CullingMachine::bounds: return tr("culling.machine_bounds");
        case algo::CullingMachine::frustum: return tr("culling.machine_frustum");
        case algo::CullingMachine::detail: return tr("culling.machine_detail");
        case algo::CullingMachine::occluders: return tr("culling.machine_occluders");
        case algo::CullingMachine::hiz: return tr("culling.machine_hiz");
    }
    return "?";
}

// One row per stage that ran; the stages the lesson's pipeline did not need are named on one line under the table
// (a row of dashes for each kept the lesson's result below the column's fold).
void pipeline_table(const CullingView& v) {
    // the whole pipeline's figures are the lesson's result: shown once its machine has run, not at its first step
    // (where they would answer the questions on the way)
    if (!v.done) {
        wrapped_text(tr("culling.pipeline_later"), dim_text);
        return;
    }
    std::string not_needed;
    for (const algo::StageReport& r : v.world->pipeline)
        if (!r.ran) not_needed += (not_needed.empty() ? "" : ", ") + stage_name(r.stage);
    if (!ImGui::BeginTable("pipeline", 5, ImGuiTableFlags_BordersInnerH | ImGuiTableFlags_RowBg)) return;
    // each column as wide as its widest word or number (any language, any type size)
    const float pad = 2 * ImGui::GetStyle().CellPadding.x;
    const auto wide = [&](std::initializer_list<std::string> words) {
        float w = 0;
        for (const std::string& t : words) w = std::max(w, ImGui::CalcTextSize(t.c_str()).x);
        return w + pad;
    };
    float stages = 0;
    for (const algo::StageReport& r : v.world->pipeline) stages = std::max(stages, ImGui::CalcTextSize(stage_name(r.stage).c_str()).x);
    const std::string stage = tr("culling.stage"), in = tr("culling.in"), left_out = tr("culling.left_out"), ms = tr("culling.ms");
    ImGui::TableSetupColumn(stage.c_str(), ImGuiTableColumnFlags_WidthFixed, std::max(stages + pad, wide({stage})));
    ImGui::TableSetupColumn(in.c_str(), ImGuiTableColumnFlags_WidthFixed, wide({in, "000000"}));
    ImGui::TableSetupColumn(left_out.c_str(), ImGuiTableColumnFlags_WidthFixed, wide({left_out, "000000"}));
    ImGui::TableSetupColumn(ms.c_str(), ImGuiTableColumnFlags_WidthFixed, wide({ms, "000.00"}));
    const std::string share = tr("culling.share_left_out");  // the bars: left out of what came in
    ImGui::TableSetupColumn(share.c_str());
    ImGui::TableHeadersRow();
    for (const algo::StageReport& r : v.world->pipeline) {
        if (!r.ran) continue;
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(stage_name(r.stage).c_str());
        ImGui::TableNextColumn();
        ImGui::Text("%u", r.in);
        ImGui::TableNextColumn();
        ImGui::Text("%u", r.left_out);
        ImGui::TableNextColumn();
        char ms_text[32];
        std::snprintf(ms_text, sizeof ms_text, "%.2f", r.milliseconds);
        ImGui::TextUnformatted(number_in_language(ms_text).c_str());  // "0,03" in German
        ImGui::TableNextColumn();
        // the share left out as a bar a line of text tall: the rows as close as the table's others
        ImGui::ProgressBar(r.in ? float(r.left_out) / float(r.in) : 0.0f, ImVec2(-1, ImGui::GetTextLineHeight()), "");
    }
    ImGui::EndTable();
    if (!not_needed.empty()) wrapped_text(tr("culling.not_needed_stages", {{"stages", not_needed}}), dim_text);
}

// Per object (polygons joined through shared vertices): the share of each bounding volume the object does not fill;
// "open" for a group that is not a closed solid (void space means nothing there).
void void_table(const CullingView& v) {
    const std::vector<SceneObject>& objects = v.world->objects;
    if (objects.empty()) {
        wrapped_text(tr("culling.void_few"), dim_text);
        return;
    }
    if (!ImGui::BeginTable("void", 4, ImGuiTableFlags_BordersInnerH)) return;
    for (const char* key : {"culling.object_ids", "culling.aabb_void", "culling.sphere_void", "culling.obb_void"}) ImGui::TableSetupColumn(tr(key).c_str());
    ImGui::TableHeadersRow();
    for (const SceneObject& object : objects) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(object.name.c_str());
        for (const std::optional<double>& share : {object.aabb_void, object.sphere_void, object.obb_void}) {
            ImGui::TableNextColumn();
            if (share) ImGui::Text("%.0f %%", 100 * *share);
            else ImGui::TextColored(dim_text, "%s", tr("culling.open").c_str());
        }
    }
    ImGui::EndTable();
}

}  // namespace

// The colours of the boxes the view shows now, each with its word.
std::vector<StateColour> culling_legend_entries(const CullingView& v) {
    const std::vector<ShownBox> boxes = shown_boxes(v);
    std::vector<StateColour> shown;
    const auto add_if = [&](NodeMark m, const StateColour& c) {
        if (std::any_of(boxes.begin(), boxes.end(), [&](const ShownBox& b) { return b.mark == m; })) shown.push_back(c);
    };
    add_if(NodeMark::outside, culling_colours::outside);
    add_if(NodeMark::inside, culling_colours::inside);
    add_if(NodeMark::partial, culling_colours::partial);
    add_if(NodeMark::large_enough, culling_colours::large_enough);
    add_if(NodeMark::too_small, culling_colours::too_small);
    add_if(NodeMark::occluded, culling_colours::occluded);
    add_if(NodeMark::visible, culling_colours::visible);
    if (v.world->machine == algo::CullingMachine::bounds) {  // a build's white boxes: built, or split off and still to build
        const StateColour built{"culling.mark_built_node", culling_colours::built.r, culling_colours::built.g, culling_colours::built.b};
        add_if(NodeMark::built, built);
        if (std::any_of(boxes.begin(), boxes.end(), [](const ShownBox& b) { return b.mark == NodeMark::untouched; }) &&
            std::none_of(boxes.begin(), boxes.end(), [](const ShownBox& b) { return b.mark == NodeMark::built; }))
            shown.push_back({"culling.mark_to_build", built.r, built.g, built.b});
    } else {
        add_if(NodeMark::untouched, culling_colours::built);  // the children still to test
    }
    shown.push_back(culling_colours::frustum);  // drawn in every culling view
    if (!v.occluders.empty()) shown.push_back(culling_colours::occluder);
    return shown;
}


void culling_state_panel(const CullingLesson& s, const PanelLayout& l, bool legend_in_view) {
    begin_column_box(l, Box::state, (tr("culling.title") + "###state").c_str());
    const CullingView& v = s.culling_view();
    const auto n = [](auto value) { return std::to_string(value); };
    // one clause per fact, joined by " · " (each a whole sentence in its language)
    const algo::CullingMachine m = s.culling_machine();
    std::vector<std::string> clauses;
    if (m == algo::CullingMachine::bounds)
        clauses.push_back(tr("culling.built_so_far", {{"machine", machine_name(m)}, {"built", n(v.built)},
                                                      {"nodes", n(v.world->hierarchy.nodes.size())}, {"leaves", n(v.leaves)}}));
    else if (!v.done)  // at the end the pipeline table holds the stage's kept and left out: the line names the stage
        clauses.push_back(tr(v.earlier > 0 ? "culling.so_far_after_earlier" : "culling.so_far",
                             {{"machine", machine_name(m)}, {"kept", n(v.kept)}, {"left_out", n(v.left_out)}, {"earlier", n(v.earlier)}}));
    else if (m != algo::CullingMachine::occluders)  // the occluders' shape clause names their stage itself
        clauses.push_back(machine_name(m));
    if (m == algo::CullingMachine::frustum) clauses.push_back(tr("culling.plane_tests", {{"tests", n(v.plane_tests)}}));
    if (m == algo::CullingMachine::hiz) clauses.push_back(tr("culling.texels", {{"texels", n(v.texels)}}));
    if (m == algo::CullingMachine::occluders) {
        const algo::OccluderKind k = v.world->occluders;
        std::string shape = tr(k == algo::OccluderKind::solid ? "culling.shape_solid" : k == algo::OccluderKind::proxy ? "culling.shape_proxy" : "culling.shape_planar");
        if (v.world->fusion) shape = tr("culling.shape_fused", {{"shape", shape}});
        clauses.push_back(tr("culling.occluders_shape", {{"shape", shape}}));
        if (v.world->fusion) clauses.push_back(tr("culling.fused", {{"fused", n(v.fused)}}));
    }
    std::string header;
    for (const std::string& c : clauses) header += (header.empty() ? "" : " · ") + c;
    wrapped_text(header, dim_text);
    if (!legend_in_view) state_legend(culling_legend_entries(v));
    if (s.culling_machine() != algo::CullingMachine::bounds) {  // one table: no tab bar above it
        pipeline_table(v);
        end_column_box(l, Box::state);
        return;
    }
    if (ImGui::BeginTabBar("culling tabs")) {
        if (ImGui::BeginTabItem((tr("culling.void_tab") + "###void space").c_str())) {
            void_table(v);
            ImGui::EndTabItem();
        }
        if (ImGui::BeginTabItem((tr("culling.pipeline_tab") + "###pipeline").c_str())) {
            pipeline_table(v);
            ImGui::EndTabItem();
        }
        ImGui::EndTabBar();
    }
    end_column_box(l, Box::state);
}

void walk_panel(const Walkthrough& walk, const PanelLayout& l, UiActions& out) {
    begin_column_box(l, Box::state, (tr("walk.title") + "###state").c_str());
    const auto n = [](auto value) { return std::to_string(value); };
    const algo::Camera& c = walk.camera();
    char eye[96];
    std::snprintf(eye, sizeof eye, "%.2f, %.2f, %.2f", c.eye.x, c.eye.y, c.eye.z);
    wrapped_text(tr("walk.keys"), dim_text);
    if (!walk.error().empty()) wrapped_text(tr("walk.cannot", {{"why", walk.error()}}), ImVec4(1.0f, 0.55f, 0.4f, 1));
    const algo::PipelineResult& r = walk.last();
    if (ImGui::BeginTable("walk", 4, ImGuiTableFlags_BordersInnerH | ImGuiTableFlags_RowBg)) {
        const float pad = 2 * ImGui::GetStyle().CellPadding.x;
        const auto wide = [&](std::initializer_list<std::string> words) {
            float w = 0;
            for (const std::string& t : words) w = std::max(w, ImGui::CalcTextSize(t.c_str()).x);
            return w + pad;
        };
        const std::string stage = tr("culling.stage"), in = tr("culling.in"), left_out = tr("culling.left_out"), ms = tr("culling.ms");
        ImGui::TableSetupColumn(stage.c_str(), ImGuiTableColumnFlags_WidthStretch);
        ImGui::TableSetupColumn(in.c_str(), ImGuiTableColumnFlags_WidthFixed, wide({in, "000000"}));
        ImGui::TableSetupColumn(left_out.c_str(), ImGuiTableColumnFlags_WidthFixed, wide({left_out, "000000"}));
        ImGui::TableSetupColumn(ms.c_str(), ImGuiTableColumnFlags_WidthFixed, wide({ms, "000.00"}));
        ImGui::TableHeadersRow();
        const std::vector<algo::Stage> switchable = walk.switchable();
        for (std::size_t k = 0; k < std::size(algo::all_stages); ++k) {
            const algo::Stage st = algo::all_stages[k];
            const bool can = st == algo::Stage::hse || std::find(switchable.begin(), switchable.end(), st) != switchable.end();
            if (!can) continue;
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            const auto report = std::find_if(r.stages.begin(), r.stages.end(), [&](const algo::StageReport& x) { return x.stage == st; });
            const bool drawn_by_hiz = report != r.stages.end() && st == algo::Stage::hse && !report->ran;  // Hi-Z rendered as it culled
            ImGui::PushID(int(k));
            if (st == algo::Stage::hse) ImGui::TextUnformatted((stage_name(st) + (drawn_by_hiz ? " " + tr("walk.by_hiz") : "")).c_str());
            else if (bool on = walk.on(st); ImGui::Checkbox(stage_name(st).c_str(), &on)) out.walk_stage = int(k);
            ImGui::PopID();
            if (drawn_by_hiz) {
                ImGui::TableNextColumn();
                ImGui::Text("%u", report->in);
                ImGui::TableNextColumn(), ImGui::TextColored(dim_text, "–");
                ImGui::TableNextColumn(), ImGui::TextColored(dim_text, "–");
                continue;
            }
            if (report == r.stages.end() || !report->ran) {
                for (int c2 = 0; c2 < 3; ++c2) ImGui::TableNextColumn(), ImGui::TextColored(dim_text, "–");
                continue;
            }
            ImGui::TableNextColumn();
            ImGui::Text("%u", report->in);
            ImGui::TableNextColumn();
            ImGui::Text("%u", report->left_out);
            ImGui::TableNextColumn();
            ImGui::Text("%.2f", report->milliseconds);
        }
        ImGui::EndTable();
    }
    char frame_ms[32], window_ms[32];
    std::snprintf(frame_ms, sizeof frame_ms, "%.2f", walk.frame_ms());
    std::snprintf(window_ms, sizeof window_ms, "%.1f", 1000.0 / std::max(1.0f, ImGui::GetIO().Framerate));
    const std::size_t drawn = r.kept.empty() ? 0 : std::size_t(std::count(r.kept.begin(), r.kept.end(), 1));
    wrapped_text(tr("walk.frame", {{"ms", frame_ms}, {"drawn", n(drawn)}, {"primitives", n(walk.scene().polygons.size())}, {"window", window_ms}}));
    if (walk.on(algo::Stage::hiz)) {
        bool coherent = walk.coherent();
        if (ImGui::Checkbox(tr("walk.coherent").c_str(), &coherent)) out.walk_coherent = coherent;
        wrapped_text(walk.coherent() ? tr("walk.drawn_first", {{"first", n(walk.drawn_first())}}) : tr("walk.coherence_why"), dim_text);
    }
    wrapped_text(tr("walk.eye", {{"eye", eye}}), dim_text);
    end_column_box(l, Box::state);
}

void zpyramid_canvas(const CullingView& v, const std::vector<std::uint32_t>& depth, float x, float y, float w, float h) {
    const algo::ZBufferOptions& o = v.world->zbuffer;
    const algo::ZPyramid pyramid(depth, o.viewport.width, o.viewport.height);
    const std::uint64_t far = algo::far_code(o.format, o.range);
    ImDrawList* d = begin_canvas("##zpyramid", x, y, w, h);
    const float cell = 2;
    float left = x + 12;
    const float top = y + h - 20 - cell * float(o.viewport.height);
    const std::string caption = tr("culling.pyramid");
    const ImVec2 at(left, top - 6 - ImGui::GetTextLineHeight()), size = ImGui::CalcTextSize(caption.c_str());  // above the frames, at any type size
    d->AddRectFilled(ImVec2(at.x - 3, at.y - 1), ImVec2(at.x + size.x + 3, at.y + size.y + 1), IM_COL32(20, 22, 26, 200), 3);  // over the scene's lines
    d->AddText(at, IM_COL32(220, 220, 220, 255), caption.c_str());
    for (std::size_t l = 0; l < std::min<std::size_t>(4, pyramid.levels()); ++l) {
        const float c = cell * float(1 << l);
        d->AddRectFilled(ImVec2(left - 2, top - 2), ImVec2(left + c * float(pyramid.width(l)) + 2, top + c * float(pyramid.height(l)) + 2),
                         IM_COL32(60, 62, 68, 255));
        for (int py = 0; py < pyramid.height(l); ++py)
            for (int px = 0; px < pyramid.width(l); ++px) {
                const std::uint32_t z = pyramid.at(l, px, py);
                // near codes bunch up against the far end in perspective: stretch by the square root
                const float g = z >= far ? 0.0f : 1.0f - std::sqrt(float(double(z) / double(far)));
                const auto k = ImU32(40 + 215 * std::clamp(g * 4, 0.0f, 1.0f));
                d->AddRectFilled(ImVec2(left + c * float(px), top + c * float(py)), ImVec2(left + c * float(px + 1), top + c * float(py + 1)),
                                 IM_COL32(k, k, k, 255));
            }
        // a coarse level's texels outlined: each holds the farthest depth of the 2 × 2 below it, and is seen to be larger
        if (c >= 6) {
            const float right = left + c * float(pyramid.width(l)), bottom = top + c * float(pyramid.height(l));
            for (int px = 1; px < pyramid.width(l); ++px) d->AddLine(ImVec2(left + c * float(px), top), ImVec2(left + c * float(px), bottom), IM_COL32(60, 62, 68, 255));
            for (int py = 1; py < pyramid.height(l); ++py) d->AddLine(ImVec2(left, top + c * float(py)), ImVec2(right, top + c * float(py)), IM_COL32(60, 62, 68, 255));
        }
        left += c * float(pyramid.width(l)) + 16;
    }
    ImGui::End();
}

}  // namespace hsr::viz
