#include "panels/bsp_panels.h"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <string>

#include <imgui.h>

#include "panels/panel_style.h"
#include "panels/wrapped_text.h"

namespace hsr::viz {

void bsp_state_panel(const BspSession& s, const PanelLayout& l) {
    begin_column_box(l, Box::state, "BSP tree");
    const BspSession::Stats& st = s.stats();
    char stats[200];
    std::snprintf(stats, sizeof stats, "%zu polygons in · %zu after %u splits · %zu nodes · depth %u · built in %.3f ms",
                  st.polygons_in, st.polygons_after, st.splits, st.nodes, st.depth, st.build_ms);
    wrapped_text(stats, dim_text);

    // Layout: x by in-order position, y by depth.
    const BspView& v = s.view();
    std::vector<float> x(v.nodes.size(), 0.f);
    int column = 0;
    const std::function<void(int)> place_node = [&](int n) {
        if (n < 0 || std::size_t(n) >= v.nodes.size()) return;
        place_node(v.nodes[std::size_t(n)].back);  // back subtree on the left, as the lecture's Right/Left read
        x[std::size_t(n)] = float(column++);
        place_node(v.nodes[std::size_t(n)].front);
    };
    if (!v.nodes.empty()) place_node(0);

    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const float dx = std::min(48.f, (avail.x - 24) / float(std::max(1, column)));
    const float dy = std::min(34.f, (avail.y - 20) / float(std::max(1, v.depth)));
    const auto at = [&](int n) {
        return ImVec2(origin.x + 14 + dx * x[std::size_t(n)], origin.y + 12 + dy * float(v.nodes[std::size_t(n)].depth));
    };
    ImDrawList* d = ImGui::GetWindowDrawList();
    for (std::size_t n = 0; n < v.nodes.size(); ++n) {
        const BspNodeView& node = v.nodes[n];
        if (node.parent >= 0)
            d->AddLine(at(node.parent), at(int(n)),
                       ImGui::GetColorU32(node.side_of_parent == algo::Side::front ? ImVec4(0.35f, 0.75f, 0.55f, 1)
                                                                                    : ImVec4(0.85f, 0.5f, 0.3f, 1)),
                       2);
    }
    for (std::size_t n = 0; n < v.nodes.size(); ++n) {
        const BspNodeView& node = v.nodes[n];
        const bool current = int(n) == v.current_node;
        d->AddCircleFilled(at(int(n)), 10, ImGui::GetColorU32(current ? highlight_bg : bit_clear));
        d->AddCircle(at(int(n)), 10, ImGui::GetColorU32(current ? ImVec4(0.94f, 0.89f, 0.26f, 1) : dim_text), 0, 2);
        const std::string name = node.splitter >= 0 ? v.polygons[std::size_t(node.splitter)].label : "?";
        d->AddText(ImVec2(at(int(n)).x - 4 * float(name.size()), at(int(n)).y - 8), IM_COL32_WHITE, name.c_str());
        if (node.eye_side) {  // which side of this node's plane the eye is on
            const char* side = *node.eye_side == algo::Side::front ? "eye F" : *node.eye_side == algo::Side::back ? "eye B" : "eye on";
            d->AddText(ImVec2(at(int(n)).x + 11, at(int(n)).y - 2), ImGui::GetColorU32(ImVec4(0.94f, 0.89f, 0.26f, 1)), side);
        }
    }
    ImGui::Dummy(avail);
    end_column_box(l, Box::state);
}

}  // namespace hsr::viz
