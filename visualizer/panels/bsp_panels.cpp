// SPDX-License-Identifier: MIT
#include "panels/bsp_panels.h"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <string>

#include <imgui.h>

#include "panels/fat_pixels.h"
#include "panels/panel_style.h"
#include "panels/view_side_box.h"
#include "state/bsp_painting.h"
#include "panels/wrapped_text.h"
#include "state/strings.h"

namespace hsr::viz {
namespace {
const ImVec4 front_branch(0.35f, 0.75f, 0.55f, 1), back_branch(0.85f, 0.5f, 0.3f, 1);

// DisplayBSP's order, the splitter rule and the insertion order: each rebuilds the tree (Ctrl+Z undoes it).
void tree_controls(const BspSession& s, UiActions& out) {
    const algo::BspJob& job = s.job();
    const std::string orders[] = {tr("bsp.back_to_front"), tr("bsp.front_to_back")};
    const int order = job.order == algo::Order::front_to_back ? 1 : 0;
    ImGui::SetNextItemWidth(ImGui::CalcTextSize(orders[1].c_str()).x + ImGui::GetFrameHeight() * 1.6f);
    if (ImGui::BeginCombo("###bsp order", orders[order].c_str())) {
        for (int i = 0; i < 2; ++i)
            if (ImGui::Selectable(orders[i].c_str(), i == order) && i != order)
                out.bsp_order = i == 1 ? algo::Order::front_to_back : algo::Order::back_to_front;
        ImGui::EndCombo();
    }
    ImGui::SameLine();
    constexpr algo::SplitterRule rules[] = {algo::SplitterRule::first, algo::SplitterRule::balanced,
                                            algo::SplitterRule::fewest_splits, algo::SplitterRule::weighted};
    const auto rule_name = [](algo::SplitterRule r) { return tr("bsp.splitter", {{"rule", window_strings().say(algo::term(r))}}); };
    ImGui::SetNextItemWidth(std::max(60.f, ImGui::GetContentRegionAvail().x));
    if (ImGui::BeginCombo("###bsp splitter", rule_name(job.options.splitter).c_str())) {
        for (algo::SplitterRule r : rules)
            if (ImGui::Selectable(rule_name(r).c_str(), r == job.options.splitter) && r != job.options.splitter)
                out.bsp_splitter = r;
        ImGui::EndCombo();
    }
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted(tr("bsp.insertion").c_str());
    ImGui::SameLine();
    if (ImGui::SmallButton((tr("bsp.reverse") + "###reverse").c_str())) out.bsp_reverse = true;
    ImGui::SameLine();
    if (ImGui::SmallButton((tr("bsp.shuffle") + "###shuffle").c_str())) out.bsp_shuffle = true;
}

// The tree as nodes and edges, in the room left in the current window (from the cursor), with the legend of its
// branches above it; the window's cursor ends under it.
void draw_tree(const BspView& v) {
    // the branches' legend, as many of its three parts to a line as fit
    const float right_edge = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    ImGui::PushTextWrapPos(0);  // a part wider than the box wraps
    // and, once DisplayBSP has classified the eye, what the letter under a node says
    const bool sides = std::any_of(v.nodes.begin(), v.nodes.end(), [](const BspNodeView& n) { return n.eye_side.has_value(); });
    const std::pair<ImVec4, std::string> legend[] = {{front_branch, tr("bsp.left")}, {dim_text, tr("bsp.normal_side")}, {back_branch, tr("bsp.right")},
                                                     {dim_text, sides ? tr("bsp.sides_legend") : std::string()}};
    for (std::size_t k = 0; k < 4; ++k) {
        if (legend[k].second.empty()) continue;
        if (k > 0) {
            ImGui::SameLine();
            if (ImGui::GetCursorScreenPos().x + ImGui::CalcTextSize(legend[k].second.c_str()).x > right_edge) ImGui::NewLine();
        }
        ImGui::TextColored(legend[k].first, "%s", legend[k].second.c_str());
    }
    ImGui::PopTextWrapPos();

    // Layout: x by in-order position, y by depth.
    std::vector<float> x(v.nodes.size(), 0.f);
    int column = 0;
    const std::function<void(int)> place_node = [&](int n) {
        if (n < 0 || std::size_t(n) >= v.nodes.size()) return;
        // the front subtree on the left: it is the notes' BSPnode->Left (their 'left' subspace is the plane's front)
        place_node(v.nodes[std::size_t(n)].front);
        x[std::size_t(n)] = float(column++);
        place_node(v.nodes[std::size_t(n)].back);
    };
    if (!v.nodes.empty()) place_node(0);

    // Sizes follow the type (a projector's larger type gets a larger tree); each row has room for a node and, under
    // it, the side of its plane the eye is on; the box asks for the rows the tree has.
    const float f = ImGui::GetFontSize(), r = 0.62f * f;
    int deepest = 0;
    for (const BspNodeView& node : v.nodes) deepest = std::max(deepest, int(node.depth));
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    // rows of 2.7 lines when the box has room (the eye's side under each node), down to 1.5 (beside it)
    const float row = deepest == 0 ? 0 : std::clamp((avail.y - 2 * r - f - 6) / float(deepest), 1.5f * f, 2.7f * f);
    const bool sides_below = row >= 2.5f * f;
    const float dx = std::min(3.6f * f, (avail.x - 2 * r - 8) / float(std::max(1, column - 1)));
    const bool short_sides = !sides_below || dx < 3.0f * f;  // no room for "eye B": "B"
    const auto at = [&](int n) {
        return ImVec2(origin.x + r + 4 + dx * x[std::size_t(n)], origin.y + r + 2 + row * float(v.nodes[std::size_t(n)].depth));
    };
    ImDrawList* d = ImGui::GetWindowDrawList();
    for (std::size_t n = 0; n < v.nodes.size(); ++n) {
        const BspNodeView& node = v.nodes[n];
        if (node.parent >= 0)
            d->AddLine(at(node.parent), at(int(n)),
                       ImGui::GetColorU32(node.side_of_parent == algo::Side::front ? front_branch : back_branch),
                       canvas_px(2));
    }
    for (std::size_t n = 0; n < v.nodes.size(); ++n) {
        const BspNodeView& node = v.nodes[n];
        const bool current = int(n) == v.current_node;
        const ImVec2 c = at(int(n));
        d->AddCircleFilled(c, r, ImGui::GetColorU32(current ? highlight_bg : bit_clear));
        d->AddCircle(c, r, ImGui::GetColorU32(current ? ImVec4(0.94f, 0.89f, 0.26f, 1) : dim_text), 0, canvas_px(2));
        const std::string name = node.splitter >= 0 ? v.polygons[std::size_t(node.splitter)].label : "?";
        const ImVec2 name_size = ImGui::CalcTextSize(name.c_str());
        d->AddText(ImVec2(c.x - name_size.x / 2, c.y - name_size.y / 2), IM_COL32_WHITE, name.c_str());
        if (node.eye_side) {  // which side of this node's plane the eye is on, under the node
            const bool front = *node.eye_side == algo::Side::front, back = *node.eye_side == algo::Side::back;
            const std::string side_text = tr(short_sides ? (front ? "bsp.f" : back ? "bsp.b" : "bsp.on") : (front ? "bsp.eye_f" : back ? "bsp.eye_b" : "bsp.eye_on"));
            const char* side = side_text.c_str();
            const float w = ImGui::CalcTextSize(side).x;
            const ImVec2 where = sides_below ? ImVec2(c.x - w / 2, c.y + r + 1) : ImVec2(c.x + r + 2, c.y - f / 2);
            d->AddText(where, ImGui::GetColorU32(ImVec4(0.94f, 0.89f, 0.26f, 1)), side);
        }
    }
    ImGui::Dummy(ImVec2(avail.x, row * float(deepest) + 2 * r + (sides_below ? f : 0) + 6));
}

}  // namespace

void bsp_state_panel(const BspSession& s, bool tree_in_view, const PanelLayout& l, UiActions& out) {
    begin_column_box(l, Box::state, (tr("bsp.tree") + "###bsp tree").c_str());
    wrapped_text(tree_summary(s), dim_text);
    tree_controls(s, out);
    if (!tree_in_view) draw_tree(s.view());  // else it is in the view, beside the scene (bsp_tree_canvas)
    end_column_box(l, Box::state);
}

void bsp_tree_canvas(const BspSession& s, float view_w, float view_h) {
    const BspView& v = s.view();
    // in a 2D plan above the first-person strip
    begin_view_side_box(tr("bsp.tree") + "###bsp tree in the view", view_w, view_h, v.two_d ? strip_height(view_h) : 0);
    draw_tree(v);
    end_view_side_box();
}

float strip_height(float view_h) { return std::clamp(0.2f * view_h, 80.0f, 260.0f); }

void bsp_painted_canvas(const BspSession& s, float view_w, float view_h, bool driving) {
    const BspView& v = s.view();
    const float line = ImGui::GetTextLineHeightWithSpacing();
    ImVec2 size, at;
    algo::Viewport pixels{};
    if (v.two_d) {  // a strip across the view's foot, the eye's field of view from left to right
        size = ImVec2(view_w - 32, strip_height(view_h) - line - 12);
        at = ImVec2(16, view_h - size.y - 12);
        pixels = {384, std::max(8, int(384 * size.y / size.x))};
    } else {  // the camera's picture, 4 : 3, at the lower left
        size.x = std::clamp(0.34f * view_w, 160.0f, 420.0f), size.y = size.x * 0.75f;
        at = ImVec2(16, view_h - size.y - 16);
        pixels = {240, 180};
    }
    ImDrawList* d = begin_canvas("##bsp painted", 0, 0, view_w, view_h);
    int total = 0;
    for (const auto& p : v.polygons) total += !p.replaced;
    const StringValues counts = {{"drawn", std::to_string(v.drawn)}, {"total", std::to_string(total)},
                                 {"order", tr(v.order == algo::Order::front_to_back ? "bsp.order_near_to_far" : "bsp.order_far_to_near")}};
    const std::string caption = tr(!v.two_d ? "bsp.painted" : driving ? "bsp.painted_driving" : "bsp.painted_drive", counts);
    const ImVec2 text(at.x, at.y - line - 2), extent = ImGui::CalcTextSize(caption.c_str());
    d->AddRectFilled(ImVec2(text.x - 4, text.y - 2), ImVec2(text.x + extent.x + 4, text.y + extent.y + 2), IM_COL32(20, 21, 25, 220));
    d->AddText(text, driving ? IM_COL32(240, 227, 66, 255) : IM_COL32(220, 220, 220, 255), caption.c_str());
    draw_image(d, bsp_painted_so_far(v, s.edited_scene(), pixels), at, size);
    if (v.drawn == 0) {  // an empty picture says why, not nothing (a class took it for a broken box)
        const std::string why = tr("bsp.painted_none");
        const float wrap = size.x - 24;
        const ImVec2 words = ImGui::CalcTextSize(why.c_str(), nullptr, false, wrap);
        d->AddText(ImGui::GetFont(), ImGui::GetFontSize(), ImVec2(at.x + (size.x - words.x) / 2, at.y + (size.y - words.y) / 2),
                   IM_COL32(150, 150, 150, 255), why.c_str(), nullptr, wrap);
    }
    ImGui::End();
}

}  // namespace hsr::viz
