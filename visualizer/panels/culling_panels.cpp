// SPDX-License-Identifier: MIT
#include "panels/culling_panels.h"

#include <algorithm>
#include <map>
#include <string>

#include <imgui.h>

#include "panels/panel_style.h"
#include "panels/wrapped_text.h"

namespace hsr::viz {
namespace {

void pipeline_table(const CullingView& v) {
    if (!ImGui::BeginTable("pipeline", 5, ImGuiTableFlags_BordersInnerH | ImGuiTableFlags_RowBg)) return;
    const float em = ImGui::GetFontSize();  // widths that grow with the type (projector, Ctrl+=)
    ImGui::TableSetupColumn("stage", ImGuiTableColumnFlags_WidthFixed, 5.5f * em);
    ImGui::TableSetupColumn("in", ImGuiTableColumnFlags_WidthFixed, 3.5f * em);
    ImGui::TableSetupColumn("left out", ImGuiTableColumnFlags_WidthFixed, 4.2f * em);
    ImGui::TableSetupColumn("ms", ImGuiTableColumnFlags_WidthFixed, 3 * em);
    ImGui::TableSetupColumn("");
    ImGui::TableHeadersRow();
    for (const algo::StageReport& r : v.world->pipeline) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(std::string(algo::to_string(r.stage)).c_str());
        if (!r.ran) {  // a dash in each number's column, the reason where the bar would be
            for (int k = 0; k < 3; ++k) ImGui::TableNextColumn(), ImGui::TextColored(dim_text, "–");
            ImGui::TableNextColumn();
            ImGui::TextColored(dim_text, "not needed");
            continue;
        }
        ImGui::TableNextColumn();
        ImGui::Text("%u", r.in);
        ImGui::TableNextColumn();
        ImGui::Text("%u", r.left_out);
        ImGui::TableNextColumn();
        ImGui::Text("%.2f", r.milliseconds);
        ImGui::TableNextColumn();
        ImGui::ProgressBar(r.in ? float(r.left_out) / float(r.in) : 0.0f, ImVec2(-1, 0), "");
    }
    ImGui::EndTable();
}

// Per object (polygons joined through shared vertices): the share of each bounding volume the object does not fill;
// "open" for a group that is not a closed solid (void space means nothing there).
void void_table(const CullingView& v) {
    std::vector<std::vector<algo::Vec3>> polygons;
    for (const auto& p : v.world->scene.polygons) {
        std::vector<algo::Vec3> w;
        for (const auto& q : p.vertices) w.emplace_back(q);
        polygons.push_back(std::move(w));
    }
    const bool large = polygons.size() > 20000;  // not worth joining: a scene of many objects
    const auto objects = large ? std::vector<std::vector<std::size_t>>{} : algo::connected_objects(polygons);
    if (large || objects.size() > 12) {
        ImGui::TextColored(dim_text, "(void space is shown for scenes of a few objects)");
        return;
    }
    if (!ImGui::BeginTable("void", 4, ImGuiTableFlags_BordersInnerH)) return;
    for (const char* c : {"object (ids)", "AABB void", "sphere void", "OBB void"}) ImGui::TableSetupColumn(c);
    ImGui::TableHeadersRow();
    for (const std::vector<std::size_t>& object : objects) {
        std::vector<std::vector<algo::Vec3>> polys;
        std::vector<algo::Vec3> points;
        for (std::size_t k : object) {
            polys.push_back(polygons[k]);
            points.insert(points.end(), polygons[k].begin(), polygons[k].end());
        }
        const double volume = algo::enclosed_volume(polys);
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        const auto& scene = v.world->scene.polygons;
        ImGui::Text("%d–%d", int(scene[object.front()].id), int(scene[object.back()].id));
        for (const double bv : {algo::aabb_of(points).volume(), algo::sphere_of(points).volume(), algo::obb_of(points).volume()}) {
            ImGui::TableNextColumn();
            if (const auto share = algo::void_fraction(bv, volume)) ImGui::Text("%.0f %%", 100 * *share);
            else ImGui::TextColored(dim_text, "open");
        }
    }
    ImGui::EndTable();
}

}  // namespace

void culling_state_panel(const CullingLesson& s, const PanelLayout& l) {
    begin_column_box(l, Box::state, "Culling");
    const CullingView& v = s.culling_view();
    std::string header = std::string(to_string(s.culling_machine())) + ": " + std::to_string(v.kept) + " kept, " +
                         std::to_string(v.left_out) + " left out so far";
    if (v.earlier > 0) header += " (and " + std::to_string(v.earlier) + " by the stages before)";
    if (s.culling_machine() == algo::CullingMachine::frustum) header += " · " + std::to_string(v.plane_tests) + " plane tests";
    if (s.culling_machine() == algo::CullingMachine::hiz) header += " · " + std::to_string(v.texels) + " texels tested";
    wrapped_text(header + " · V: god's eye / camera", dim_text);
    if (ImGui::BeginTabBar("culling tabs")) {
        if (s.culling_machine() == algo::CullingMachine::bounds && ImGui::BeginTabItem("void space")) {
            void_table(v);
            ImGui::EndTabItem();
        }
        if (ImGui::BeginTabItem("pipeline")) {
            pipeline_table(v);
            ImGui::EndTabItem();
        }
        ImGui::EndTabBar();
    }
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
    d->AddText(ImVec2(left, top - 20), IM_COL32(220, 220, 220, 255), "Z-pyramid: levels 0 to 3 (bright = near, dark = far)");
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
        left += c * float(pyramid.width(l)) + 16;
    }
    ImGui::End();
}

}  // namespace hsr::viz
