// SPDX-License-Identifier: MIT
#include "panels/scanline_panels.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include <imgui.h>

#include "panels/fat_pixels.h"
#include "panels/panel_style.h"
#include "panels/view_side_box.h"
#include "panels/wrapped_text.h"
#include "state/strings.h"

namespace hsr::viz {

namespace {

constexpr float canvas_margin = 24, canvas_title = 24;  // around the grid; the line above it

// The side of one pixel of the grid when the canvas is w × h points.
float grid_cell(const ScanView& v, float w, float h) {
    return std::max(2.0f, std::min((w - 2 * canvas_margin) / float(v.viewport.width),
                                   (h - 2 * canvas_margin - canvas_title) / float(v.viewport.height)));
}

}  // namespace

void scanline_canvas(const ScanLineSession& s, float x, float y, float w, float h) {
    const ScanView& v = s.view();
    ImDrawList* d = begin_canvas("##scanline canvas", x, y, w, h);
    const float margin = canvas_margin;
    const float cell = grid_cell(v, w, h);
    const ImVec2 o(x + margin, y + margin + 20);
    d->AddText(ImVec2(o.x, y + margin - 2), IM_COL32(220, 220, 220, 255), tr("scanline.image").c_str());
    pixel_grid(d, o, cell, v.viewport, [&](int px, int py) {
        const std::int32_t k = v.owner[std::size_t(py) * std::size_t(v.viewport.width) + std::size_t(px)];
        return k >= 0 ? rgb((*v.polygons)[std::size_t(k)].color) : rgb({40, 43, 50});
    });
    grid_numbers(d, o, cell, v.viewport);
    // each polygon outlined in its own colour, so that its name tag and its edges are one object to the eye
    for (const auto& p : *v.polygons) {
        const ImVec4 c(p.color.r / 255.f, p.color.g / 255.f, p.color.b / 255.f, 0.85f);
        outline(d, o, cell, p, ImGui::GetColorU32(c), canvas_px(1.5f));
    }
    for (std::uint32_t e : v.active) {
        const algo::EdgeEntry& edge = (*v.edges)[e];
        d->AddLine(on_grid(o, cell, edge.a), on_grid(o, cell, edge.b), IM_COL32(255, 255, 255, 255), canvas_px(3));
    }
    std::vector<ImVec4> taken;  // the words placed so far: the polygons' names keep off the edges' numbers
    // each active edge's number, as the edge table and the questions name it, low on the edge: the top, where edges
    // meet at a triangle's tip and the line's in/out words stand, is crowded. The edges the current line is about
    // to enter are named too: a question asks about them before they are in the table.
    std::vector<std::uint32_t> named = v.active;
    if (v.line >= 0)
        for (std::uint32_t e = 0; e < v.edges->size(); ++e)
            if ((*v.edges)[e].first_row == v.line && std::find(named.begin(), named.end(), e) == named.end()) named.push_back(e);
    for (std::uint32_t e : named) {
        const algo::EdgeEntry& edge = (*v.edges)[e];
        const ImVec2 a = on_grid(o, cell, edge.a), b = on_grid(o, cell, edge.b);
        const std::string text = tr("scanline.edge_label", {{"edge", std::to_string(e)}});
        const ImVec2 top = a.y <= b.y ? a : b, bottom = a.y <= b.y ? b : a;
        const ImVec2 size = ImGui::CalcTextSize(text.c_str());
        // three quarters down the edge, else higher up where another edge's number took that place (two edges
        // meeting low in a triangle had their numbers side by side, each seeming to name the other)
        const auto point_at = [&](float t) { return ImVec2(top.x + (bottom.x - top.x) * t, top.y + (bottom.y - top.y) * t); };
        const auto box_at = [&](float t) {
            const ImVec2 at(point_at(t).x + 8, point_at(t).y - size.y / 2);
            return ImVec4(at.x - 2, at.y, at.x + size.x + 2, at.y + size.y);
        };
        float along = 0.75f;
        for (const float t : {0.75f, 0.6f, 0.45f, 0.9f, 0.3f}) {
            const ImVec4 c = box_at(t);
            if (std::none_of(taken.begin(), taken.end(), [&](const ImVec4& other) { return boxes_overlap(c, other); })) {
                along = t;
                break;
            }
        }
        // a dot on its edge, joined to the number: where edges cross, the number says which line it names
        const ImVec4 box = box_at(along);
        const ImVec2 on_edge = point_at(along);
        d->AddLine(on_edge, ImVec2(box.x, (box.y + box.w) / 2), IM_COL32(255, 255, 255, 255), canvas_px(1.5f));
        d->AddCircleFilled(on_edge, canvas_px(3.5f), IM_COL32(255, 255, 255, 255));
        d->AddRectFilled(ImVec2(box.x, box.y), ImVec2(box.z, box.w), IM_COL32(20, 22, 26, 200), 2);
        d->AddText(ImVec2(box.x + 2, box.y), IM_COL32(255, 255, 255, 255), text.c_str());
        taken.push_back(box);
    }
    // the names keep off the line being scanned, its crossings' words and the pixels a question there asks about
    const float ly = o.y + (float(v.line) + 0.5f) * cell, word_band = 9 + ImGui::GetTextLineHeight();
    if (v.line >= 0) taken.push_back(ImVec4(o.x, ly - std::max(word_band, cell / 2), o.x + cell * float(v.viewport.width), ly + std::max(word_band, cell / 2)));
    for (std::size_t k = 0; k < v.polygons->size(); ++k) polygon_name(d, o, cell, v.viewport, (*v.polygons)[k], "#" + std::to_string(k), taken);
    if (v.line >= 0) {
        d->AddLine(ImVec2(o.x - 8, ly), ImVec2(o.x + cell * float(v.viewport.width) + 8, ly), IM_COL32(255, 230, 90, 255), canvas_px(2));
        // each crossing's word above the line, or below it where it would run into the word before it
        float above_end = -1e30f, below_end = -1e30f;
        for (const Crossing& c : v.crossings) {
            const float cx = o.x + float(c.x) * cell;
            const ImU32 colour = c.entering ? IM_COL32(90, 220, 130, 255) : IM_COL32(240, 80, 60, 255);
            d->AddCircleFilled(ImVec2(cx, ly), 6, colour);
            const std::string word = tr(c.entering ? "scanline.in" : "scanline.out");
            const float tw = ImGui::CalcTextSize(word.c_str()).x, tx = cx - tw / 2;
            const bool below = tx < above_end + 4 && tx >= below_end + 4;
            float& end = below ? below_end : above_end;
            const ImVec2 at(tx, below ? ly + 9 : ly - 9 - ImGui::GetTextLineHeight());
            d->AddRectFilled(ImVec2(at.x - 2, at.y), ImVec2(at.x + tw + 2, at.y + ImGui::GetTextLineHeight()), IM_COL32(20, 22, 26, 200), 2);
            d->AddText(at, colour, word.c_str());
            end = tx + tw;
        }
        // classic: where the planes were compared (a ring) and the extra intersections where two pierce (an orange bar)
        for (const DepthMark& m : v.marks) {
            const float mx = o.x + float(m.x) * cell;
            if (m.piercing) {
                d->AddLine(ImVec2(mx, ly - cell * 0.6f), ImVec2(mx, ly + cell * 0.6f), IM_COL32(255, 150, 40, 255), canvas_px(4));
                d->AddText(ImVec2(mx - 8, ly + 10), IM_COL32(255, 150, 40, 255), tr("scanline.pierce_mark").c_str());
            } else {
                d->AddCircle(ImVec2(mx, ly), 7, IM_COL32(255, 255, 255, 255), 0, canvas_px(2));
            }
        }
    }
    ImGui::End();
}

namespace {

// The current scan line, or a dash before the first and after the last (where the view's line is −1).
std::string line_number(const ScanView& v) { return v.line < 0 ? "–" : std::to_string(v.line); }
// The active edges counted on a line; none once the last line is done (the table keeps its last line's edges)
std::string active_count(const ScanView& v) { return std::to_string(v.line < 0 ? 0 : v.active.size()); }

// The classic's tables as the Brown notes draw them: ET entry (x, y_max, Δx, ID), PT entry (ID, plane eq., in-out).
void classic_tables(const ScanLineSession& s, UiActions& out) {
    const ScanView& v = s.view();
    bool piercings = s.finds_piercings();
    if (ImGui::Checkbox((tr("scanline.find_piercings") + "###piercings").c_str(), &piercings)) out.find_piercings = piercings;
    wrapped_text(tr("scanline.classic_summary", {{"line", line_number(v)}, {"active", active_count(v)},
                                                 {"compared", std::to_string(v.compared)}, {"piercings", std::to_string(v.piercings)}}),
                 dim_text);
    const auto width = [](const std::string& t) { return ImGui::CalcTextSize(t.c_str()).x; };
    const std::string left = tr("scanline.left"), right = tr("scanline.right"), in = tr("scanline.in");
    // The polygon table: each plane as the lecture's F′(x, y) = c0 + a·x + b·y, the window depth at pixel (x, y)
    ImGui::TextUnformatted(tr("scanline.polygon_table").c_str());
    const std::string pt[] = {"ID", tr("scanline.plane"), tr("scanline.in_out")};
    if (ImGui::BeginTable("polygons", 3, ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg)) {
        ImGui::TableSetupColumn(pt[0].c_str(), ImGuiTableColumnFlags_WidthFixed, width("#000"));
        ImGui::TableSetupColumn(pt[1].c_str());
        ImGui::TableSetupColumn(pt[2].c_str(), ImGuiTableColumnFlags_WidthFixed, std::max(width(pt[2]), width(in)));
        ImGui::TableHeadersRow();
        for (std::size_t p = 0; p < v.polygons->size(); ++p) {
            const algo::ScreenPolygon& poly = (*v.polygons)[p];
            if (poly.status != algo::ScreenStatus::drawn) continue;
            ImGui::TableNextRow();
            if (v.in[p]) ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg0, ImGui::GetColorU32(highlight_bg));
            ImGui::TableNextColumn();
            ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(rgb(poly.color)), "#%zu", p);
            ImGui::TableNextColumn();
            char plane[160];  // + 0: no "−0"; wrapped at spaces only, never inside a number
            std::snprintf(plane, sizeof plane, "z = %.4g %+.4g·x %+.4g·y", poly.plane.c0 + 0.0, poly.plane.per_x + 0.0, poly.plane.per_y + 0.0);
            wrapped_text(plane);
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(v.in[p] ? in.c_str() : "");
        }
        ImGui::EndTable();
    }
    ImGui::TextUnformatted(tr("scanline.edge_table").c_str());
    if (!v.table_built) return wrapped_text(tr("scanline.table_pending"), dim_text);  // else it answers "how many edges?"
    const std::string et[] = {tr("scanline.edge"), "x", "y_max", "Δx", tr("scanline.polygon"), tr("scanline.side")};
    if (ImGui::BeginTable("classic edges", 6, ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg)) {
        const float widths[] = {std::max(width(et[0]), width("000")), width("-00.00"), std::max(width(et[2]), width("00")),
                                width("-00.00"), std::max(width(et[4]), width("#000"))};
        for (int c = 0; c < 5; ++c) ImGui::TableSetupColumn(et[c].c_str(), ImGuiTableColumnFlags_WidthFixed, widths[c]);
        ImGui::TableSetupColumn(et[5].c_str());
        ImGui::TableHeadersRow();
        for (std::size_t i = 0; i < v.edges->size(); ++i) {
            const algo::EdgeEntry& e = (*v.edges)[i];
            const algo::EdgeFields f = algo::edge_fields(e);
            ImGui::TableNextRow();
            if (std::find(v.active.begin(), v.active.end(), std::uint32_t(i)) != v.active.end())
                ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg0, ImGui::GetColorU32(highlight_bg));
            ImGui::TableNextColumn();
            ImGui::Text("%zu", i);
            ImGui::TableNextColumn();
            ImGui::Text("%.2f", f.x);
            ImGui::TableNextColumn();
            ImGui::Text("%d", f.y_max);
            ImGui::TableNextColumn();
            ImGui::Text("%.2f", f.dx);
            ImGui::TableNextColumn();
            ImGui::Text("#%u", unsigned(e.polygon));
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(e.left ? left.c_str() : right.c_str());
        }
        ImGui::EndTable();
    }
}

}  // namespace

namespace {

// The tables of the box they are in (the column's state box, or the box in the view).
void tables(const ScanLineSession& s, UiActions& out) {
    const ScanView& v = s.view();
    if (v.classic) return classic_tables(s, out);
    wrapped_text(tr("scanline.summary", {{"line", line_number(v)}, {"active", active_count(v)},
                                         {"spans", std::to_string(v.spans)}}),
                 dim_text);
    // columns as wide as their words at any scale; the polygon named as the machine's sentences name it (#0 first).
    // No "side" column: the notes flip a polygon's flag at each of its edges (parity), and a column that said which
    // edges bring their polygon in would answer the lesson's first question before the walk reaches it. The last
    // column fills in as the walk crosses each edge on this line.
    const std::string headers[] = {tr("scanline.edge"), tr("scanline.polygon"), tr("scanline.lines"), tr("scanline.flipped_to")};
    const std::string in = tr("scanline.in"), out_word = tr("scanline.out");
    const auto width = [](const std::string& t) { return ImGui::CalcTextSize(t.c_str()).x; };
    const float widths[] = {std::max(width(headers[0]), width("000")), std::max(width(headers[1]), width("#000")),
                            std::max(width(headers[2]), width("00–00"))};
    if (!v.table_built) return wrapped_text(tr("scanline.table_pending"), dim_text);  // else it answers "how many edges?"
    if (ImGui::BeginTable("edges", 4, ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg)) {
        for (int c = 0; c < 3; ++c) ImGui::TableSetupColumn(headers[c].c_str(), ImGuiTableColumnFlags_WidthFixed, widths[c]);
        ImGui::TableSetupColumn(headers[3].c_str());
        ImGui::TableHeadersRow();
        for (std::size_t i = 0; i < v.edges->size(); ++i) {
            const algo::EdgeEntry& e = (*v.edges)[i];
            ImGui::TableNextRow();
            if (std::find(v.active.begin(), v.active.end(), std::uint32_t(i)) != v.active.end())
                ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg0, ImGui::GetColorU32(highlight_bg));
            ImGui::TableNextColumn();
            ImGui::Text("%zu", i);
            ImGui::TableNextColumn();
            ImGui::Text("#%u", unsigned(e.polygon));
            ImGui::TableNextColumn();
            ImGui::Text("%d–%d", e.first_row, e.end_row - 1);
            ImGui::TableNextColumn();
            const auto crossed = std::find_if(v.crossings.begin(), v.crossings.end(), [&](const Crossing& c) { return c.edge == i; });
            if (crossed != v.crossings.end()) ImGui::TextUnformatted(crossed->entering ? in.c_str() : out_word.c_str());
        }
        ImGui::EndTable();
    }
}

std::string tables_title(const ScanView& v) { return tr(v.classic ? "scanline.tables" : "scanline.edge_table") + "###edge table"; }

}  // namespace

void scanline_state_panel(const ScanLineSession& s, const PanelLayout& l, UiActions& out) {
    begin_column_box(l, Box::state, tables_title(s.view()).c_str());
    tables(s, out);
    end_column_box(l, Box::state);
}

float scanline_foot_share(const ScanLineSession& s, float view_w, float view_h) {
    const ScanView& v = s.view();
    if (v.classic || !foot_box_fits(view_w) || view_h <= 0) return 0;
    // the box's height: its title, the summary line, the header and one row per edge, its padding
    const ImGuiStyle& st = ImGui::GetStyle();
    const float row = ImGui::GetTextLineHeight() + 2 * st.CellPadding.y + 1;
    const float need = ImGui::GetFrameHeight() + 2 * st.WindowPadding.y + ImGui::GetTextLineHeightWithSpacing() +
                       float(v.edges->size() + 1) * row + st.ItemSpacing.y + 8 + 8;
    const float share = need / view_h;
    if (share > 0.5f) return 0;
    const float beside = grid_cell(v, view_w * (1 - scanline_tables_share), view_h), under = grid_cell(v, view_w, view_h * (1 - share));
    return under > beside ? share : 0;
}

void scanline_tables_foot_box(const ScanLineSession& s, float view_w, float view_h, float share, UiActions& out) {
    begin_view_foot_box(tables_title(s.view()), view_w, view_h, share);
    tables(s, out);
    end_view_side_box();
}

void scanline_tables_box(const ScanLineSession& s, float view_w, float view_h, UiActions& out) {
    begin_view_side_box(tables_title(s.view()), view_w, view_h, 0, scanline_tables_share);
    tables(s, out);
    end_view_side_box();
}

}  // namespace hsr::viz
