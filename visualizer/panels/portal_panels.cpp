// SPDX-License-Identifier: MIT
// [SECTION] the floor plan: fitting, cells, walls and openings
// [SECTION] what each lesson adds to the plan: the sightline being tested, or the eye and its frusta
// [SECTION] the state panels: PVS matrix, stab tree, counts
#include "panels/portal_panels.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/geometric.hpp>
#include <imgui.h>

#include "panels/fat_pixels.h"
#include "panels/panel_style.h"
#include "panels/state_legend.h"
#include "panels/wrapped_text.h"
#include "state/elevation.h"
#include "state/strings.h"

namespace hsr::viz {
namespace {

using algo::Vec2;

const ImU32 wall_colour = IM_COL32(200, 203, 210, 255);
const ImU32 opening_colour = okabe_ito_u32(algo::okabe_ito::sky_blue);
const ImU32 eye_colour = okabe_ito_u32(algo::okabe_ito::yellow);
const ImU32 found_colour = IM_COL32(0, 200, 140, 255);
const ImU32 blocked_colour = okabe_ito_u32(algo::okabe_ito::vermillion);
const ImU32 background = IM_COL32(26, 28, 33, 255);
ImU32 cell_colour(const StateColour& c) { return ImGui::GetColorU32(ImVec4(c.r, c.g, c.b, 1)); }

// ── [SECTION] the floor plan ────────────────────────────────────────────────────────────────────────────────
struct PlanFit {
    ImVec2 origin;  // screen point of plan (lo.x, hi.y)
    double scale;
    Vec2 lo, hi;
    ImVec2 operator()(Vec2 p) const { return {origin.x + float((p.x - lo.x) * scale), origin.y + float((hi.y - p.y) * scale)}; }
    Vec2 plan(ImVec2 s) const { return {lo.x + (s.x - origin.x) / scale, hi.y - (s.y - origin.y) / scale}; }
};

PlanFit fit(const algo::CellModel& m, float x, float y, float w, float h) {
    Vec2 lo(1e300), hi(-1e300);
    for (const auto& c : m.cells)
        for (const Vec2& p : c.outline) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const double margin = 40, scale = std::min((w - 2 * margin) / (hi.x - lo.x), (h - 2 * margin - 30) / (hi.y - lo.y));
    const float pw = float((hi.x - lo.x) * scale), ph = float((hi.y - lo.y) * scale);
    return {ImVec2(x + (w - pw) / 2, y + 30 + (h - 30 - ph) / 2), scale, lo, hi};
}

Vec2 mean_of(const std::vector<Vec2>& o) {
    Vec2 m(0);
    for (const Vec2& p : o) m += p / double(o.size());
    return m;
}

// Cells filled by `fill(cell)`, their walls, the openings cut in them, and their names.
template <class Fill>
void draw_plan(ImDrawList* d, const PlanFit& f, const algo::CellModel& m, Fill fill) {
    for (std::uint32_t c = 0; c < m.cells.size(); ++c) {
        std::vector<ImVec2> pts;
        for (const Vec2& p : m.cells[c].outline) pts.push_back(f(p));
        d->AddConvexPolyFilled(pts.data(), int(pts.size()), fill(c));
    }
    for (const auto& c : m.cells)
        for (std::size_t i = 0; i < c.outline.size(); ++i) d->AddLine(f(c.outline[i]), f(c.outline[(i + 1) % c.outline.size()]), wall_colour, canvas_px(2));
    for (std::size_t k = 0; k < m.portals.size(); k += 2) {  // each opening once
        const auto& p = m.portals[k];
        d->AddLine(f(p.left), f(p.right), background, canvas_px(4));
        d->AddLine(f(p.left), f(p.right), opening_colour, canvas_px(1.5f));
    }
    if (m.cells.size() <= 64)  // each opening named by the cells it joins (the chapters' "door A→D"), beside it
        for (std::size_t k = 0; k < m.portals.size(); k += 2) {
            const auto& p = m.portals[k];
            const std::string name = m.cells[p.from].name + "–" + m.cells[p.to].name;
            const ImVec2 a = f(p.left), b = f(p.right), size = ImGui::CalcTextSize(name.c_str());
            const float len = std::max(1.0f, std::hypot(b.x - a.x, b.y - a.y));
            const ImVec2 normal((a.y - b.y) / len, (b.x - a.x) / len);  // beside the opening, on its left
            const float off = 0.5f * std::abs(normal.x) * size.x + 0.5f * std::abs(normal.y) * size.y + canvas_px(5);
            // near one end of the opening: a sightline or a frustum's edge usually crosses its middle
            const ImVec2 c(a.x + (b.x - a.x) * 0.2f + normal.x * off - size.x / 2, a.y + (b.y - a.y) * 0.2f + normal.y * off - size.y / 2);
            d->AddRectFilled(ImVec2(c.x - 2, c.y), ImVec2(c.x + size.x + 2, c.y + size.y), IM_COL32(14, 15, 18, 200), 2);
            d->AddText(c, IM_COL32(150, 190, 235, 255), name.c_str());
        }
    if (m.cells.size() <= 64)
        for (const auto& c : m.cells) {
            const ImVec2 at = f(mean_of(c.outline));
            const ImVec2 size = ImGui::CalcTextSize(c.name.c_str());
            d->AddText(ImVec2(at.x - size.x / 2, at.y - size.y / 2), IM_COL32(235, 235, 235, 255), c.name.c_str());
        }
}

// A line through the plan from p along d, as far as the plan's box reaches.
void long_line(ImDrawList* d, const PlanFit& f, Vec2 p, Vec2 dir, ImU32 colour, float thickness, bool both_ways) {
    const double reach = glm::length(f.hi - f.lo) * 1.5;
    d->AddLine(f(both_ways ? p - dir * reach : p), f(p + dir * reach), colour, thickness);
}

// The frustum's name, f1 (the eye's), f2, f3 … (each narrowing), as the lesson and the notes name them: on a dark
// backing, `distance` points from the eye along `dir` (the middle of its wedge), in its lines' colour.
void frustum_name(ImDrawList* d, const PlanFit& f, Vec2 eye, Vec2 dir, float distance, std::size_t number, ImU32 colour) {
    const std::string text = "f" + std::to_string(number);
    const ImVec2 at = f(eye + dir * double(canvas_px(distance) / f.scale)), size = ImGui::CalcTextSize(text.c_str());
    const float pad = canvas_px(3);
    const ImVec2 a(at.x - size.x / 2 - pad, at.y - size.y / 2 - pad / 2), b(at.x + size.x / 2 + pad, at.y + size.y / 2 + pad / 2);
    d->AddRectFilled(a, b, IM_COL32(14, 15, 18, 215), pad);
    d->AddText(ImVec2(a.x + pad, a.y + pad / 2), colour | IM_COL32_A_MASK, text.c_str());
}

// ── [SECTION] what each lesson adds ─────────────────────────────────────────────────────────────────────────
void pvs_plan(const PvsSession& s, ImDrawList* d, const PlanFit& f) {
    const PvsView& v = s.view();
    const auto& m = v.world->model;
    const auto n = v.world->pvs.cells;
    draw_plan(d, f, m, [&](std::uint32_t c) {
        if (v.source < 0) return cell_colour(portal_cell_colours::out_of_pvs);
        if (std::int32_t(c) == v.source) return cell_colour(portal_cell_colours::being_drawn);
        return cell_colour(v.matrix[std::size_t(v.source) * n + c] ? portal_cell_colours::in_pvs : portal_cell_colours::out_of_pvs);
    });
    for (std::uint32_t k : v.sequence) {
        const auto& p = m.portals[k];
        d->AddLine(f(p.left), f(p.right), v.found ? found_colour : blocked_colour, canvas_px(5));
    }
    // a plan line through the run (orange-red when it passes in the plan only: in 3D above or below an opening)
    if ((v.found || v.blocked_in_3d) && !v.sequence.empty())
        long_line(d, f, v.sight_point, v.sight_direction, v.found ? found_colour : blocked_colour, canvas_px(1.5f), true);
}

void render_plan(const PortalRenderSession& s, ImDrawList* d, const PlanFit& f) {
    const PortalView& v = s.view();
    const auto& m = v.world->model;
    std::vector<std::uint8_t> in_pvs(m.cells.size(), 0);
    for (std::uint32_t c : v.pvs_row) in_pvs[c] = 1;
    draw_plan(d, f, m, [&](std::uint32_t c) {
        if (std::int32_t(c) == v.cell) return cell_colour(portal_cell_colours::being_drawn);
        if (v.visited[c]) return cell_colour(portal_cell_colours::visited);
        return cell_colour(in_pvs[c] ? portal_cell_colours::in_pvs : portal_cell_colours::out_of_pvs);
    });
    // walls drawn (in their cell's colour) or culled (dim); floors are not shown in the plan
    for (std::size_t k = 0; k < m.polygons.size(); ++k) {
        const auto& p = m.polygons[k];
        if (v.fate[k] == PolygonFate::untouched || p.plane.n.y > 0.5) continue;
        Vec2 a(1e300), b(-1e300);  // a wall's ends in the plan: its extreme points along the wall
        const Vec2 along(-p.plane.n.z, -p.plane.n.x);
        double lo = 1e300, hi = -1e300;
        for (const auto& q : p.vertices) {
            const Vec2 pq = algo::plan_point(q);
            const double t = glm::dot(pq, along);
            if (t < lo) lo = t, a = pq;
            if (t > hi) hi = t, b = pq;
        }
        const bool drawn = v.fate[k] == PolygonFate::drawn;
        d->AddLine(f(a), f(b), drawn ? rgb(p.color) : IM_COL32(90, 60, 50, 255), canvas_px(drawn ? 4.0f : 2.0f));
    }
    // the frusta: the eye's, and each narrowing on the way to the cell being visited
    const Vec2 eye = algo::plan_point(v.camera.eye), look = glm::normalize(algo::plan_point(v.camera.target) - eye);
    const double half = std::atan(std::tan(v.camera.fov_y * M_PI / 360) * v.camera.aspect);
    for (double side : {-half, half})
        long_line(d, f, eye, {look.x * std::cos(side) - look.y * std::sin(side), look.x * std::sin(side) + look.y * std::cos(side)},
                  okabe_ito_u32(algo::okabe_ito::yellow, 120), canvas_px(1), false);
    {
        const double side = half * 0.85;  // f1's name just inside its right edge
        frustum_name(d, f, eye, {look.x * std::cos(side) - look.y * std::sin(side), look.x * std::sin(side) + look.y * std::cos(side)},
                     230, 1, okabe_ito_u32(algo::okabe_ito::yellow));
    }
    const ImU32 wedge_colours[] = {IM_COL32(0, 200, 140, 200), okabe_ito_u32(algo::okabe_ito::sky_blue, 200), okabe_ito_u32(algo::okabe_ito::reddish_purple, 200)};
    for (std::size_t i = 0; i < v.passed.size(); ++i) {
        double a0 = 1e300, a1 = -1e300;
        Vec2 d0{}, d1{};
        for (const auto& q : v.passed[i].section) {  // the narrowed frustum's extreme directions from the eye, in the plan
            const Vec2 dir = glm::normalize(algo::plan_point(q) - eye);
            const double a = std::atan2(look.x * dir.y - look.y * dir.x, glm::dot(look, dir));
            if (a < a0) a0 = a, d0 = dir;
            if (a > a1) a1 = a, d1 = dir;
        }
        for (const Vec2& dir : {d0, d1}) long_line(d, f, eye, dir, wedge_colours[i % 3], canvas_px(2), false);
        frustum_name(d, f, eye, glm::normalize(d0 + d1), 90 + 45 * float(i), i + 2, wedge_colours[i % 3]);
    }
    if (v.portal >= 0) {
        const auto& p = m.portals[std::size_t(v.portal)];
        d->AddLine(f(p.left), f(p.right), v.verdict == algo::PortalVerdict::passed ? found_colour : blocked_colour, canvas_px(5));
    }
    d->AddCircleFilled(f(eye), canvas_px(7), eye_colour);
    d->AddLine(f(eye), f(eye + look * (24 / f.scale)), eye_colour, canvas_px(3));
    // the polygons the narration and the questions name, by their ids, on a dark backing beside their place
    float below = 0;
    for (std::uint32_t k : named_polygons(v)) {
        const std::string text = tr("portals.label_polygon", {{"id", std::to_string(m.polygons[k].id)}});
        const ImVec2 at = f(algo::plan_point(algo::centroid(m.polygons[k].vertices))), size = ImGui::CalcTextSize(text.c_str());
        const float pad = canvas_px(3), x = at.x + canvas_px(8), y = at.y - size.y / 2 + below;
        d->AddRectFilled(ImVec2(x - pad, y - pad / 2), ImVec2(x + size.x + pad, y + size.y + pad / 2), IM_COL32(14, 15, 18, 215), pad);
        d->AddText(ImVec2(x, y), IM_COL32(242, 242, 242, 255), text.c_str());
        below += size.y + 2 * pad;  // two named walls side by side do not cover each other
    }
}

}  // namespace

namespace {

// The canvas's window and background, and the fit of the plan into its top `fit_h` points (all of it when 0);
// end_plan_canvas writes the caption.
PlanFit begin_plan_canvas(const algo::CellModel& m, float x, float y, float w, float h, float fit_h = 0) {
    place(x, y, w, h);
    ImGui::Begin("##floor plan", nullptr, fixed | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar |
                                              ImGuiWindowFlags_NoBringToFrontOnFocus);
    ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(x, y), ImVec2(x + w, y + h), background);
    return fit(m, x, y, w, fit_h > 0 ? fit_h : h - legend_height());  // the legend under the plan
}

// The caption, and the legend of the cells' colours under the plan.
void end_plan_canvas(float x, float y, float plan_h, const char* caption, std::span<const StateColour> legend) {
    ImGui::GetWindowDrawList()->AddText(ImVec2(x + 16, y + 10), IM_COL32(160, 163, 170, 255), caption);
    canvas_legend(ImGui::GetWindowDrawList(), x + 16, y + plan_h, legend);
    ImGui::End();
}

// The PVS lesson's cells: the source cell in the eye's colour, the cells of its PVS, the others.
constexpr std::array pvs_legend{StateColour{"portals.cell_source", portal_cell_colours::being_drawn.r, portal_cell_colours::being_drawn.g, portal_cell_colours::being_drawn.b},
                                portal_cell_colours::in_pvs, portal_cell_colours::out_of_pvs};

}  // namespace

namespace {

// Does any opening stop short of the floor or the ceiling? Then heights matter, and the PVS lesson draws the
// elevation of the run of openings being tested under the plan.
// Whether heights matter: the openings share no band of heights (low windows and high ones), so a level line may not
// pass where the plan's lines do. Doors that all reach from the floor to a height share one: the plan says it all,
// and the plan keeps the whole canvas.
bool openings_have_heights(const algo::CellModel& m) {
    double highest_bottom = -1e300, lowest_top = 1e300;
    for (const auto& p : m.portals) {
        double bottom = 1e300, top = -1e300;
        for (const auto& v : p.opening) bottom = std::min(bottom, v.y), top = std::max(top, v.y);
        highest_bottom = std::max(highest_bottom, bottom), lowest_top = std::min(lowest_top, top);
    }
    return !m.portals.empty() && highest_bottom >= lowest_top - m.tol.epsilon;
}

// The elevation along the plan line of the last sightline test: walls at the openings' distances with their gaps,
// and the steepest and shallowest lines through the gaps they pass (green through all of them; orange-red when they
// pass above or below the next one).
void elevation_canvas(const PvsView& v, ImDrawList* d, float x, float y, float w, float h) {
    const ImU32 text = IM_COL32(200, 203, 210, 255), dim = IM_COL32(150, 153, 160, 255);
    d->AddText(ImVec2(x + 16, y), dim, tr("portals.elevation").c_str());
    const auto e = v.sequence.empty() || !(v.found || v.blocked_in_3d) ? std::nullopt
                                                                       : elevation_of(v.world->model, v.sequence, v.sight_point, v.sight_direction);
    if (!e) {
        d->AddText(ImVec2(x + 16, y + ImGui::GetTextLineHeightWithSpacing()), dim, tr("portals.no_run").c_str());
        return;
    }
    double s0 = e->gaps.front().s, s1 = s0;
    for (const auto& g : e->gaps) s0 = std::min(s0, g.s), s1 = std::max(s1, g.s);
    const double pad = std::max(0.35 * (s1 - s0), 0.5);
    s0 -= pad, s1 += pad;
    const float line = ImGui::GetTextLineHeightWithSpacing();
    const std::string ceiling = tr("portals.ceiling"), floor = tr("portals.floor");
    const float top = y + line + 10, bottom = y + h - line - 10, left = x + 40,
                right = x + w - 16 - std::max(ImGui::CalcTextSize(ceiling.c_str()).x, ImGui::CalcTextSize(floor.c_str()).x);
    const double scale = std::min(double(right - left) / (s1 - s0), double(bottom - top) / e->height);
    const float r = left + float((s1 - s0) * scale);
    const auto at = [&](double s, double height) { return ImVec2(left + float((s - s0) * scale), bottom - float(height * scale)); };
    d->AddLine(at(s0, 0), at(s1, 0), wall_colour, canvas_px(2));  // floor and ceiling
    d->AddLine(at(s0, e->height), at(s1, e->height), wall_colour, canvas_px(2));
    d->AddText(ImVec2(r + 4, at(s1, e->height).y - 8), dim, ceiling.c_str());
    d->AddText(ImVec2(r + 4, at(s1, 0).y - 8), dim, floor.c_str());
    for (std::size_t k = 0; k < e->gaps.size(); ++k) {
        const ElevationGap& g = e->gaps[k];
        const bool missed = k == e->reached;
        d->AddLine(at(g.s, 0), at(g.s, g.bottom), wall_colour, canvas_px(3));
        d->AddLine(at(g.s, g.top), at(g.s, e->height), wall_colour, canvas_px(3));
        d->AddLine(at(g.s, g.bottom), at(g.s, g.top), missed ? blocked_colour : opening_colour, canvas_px(5));
        char label[48];
        std::snprintf(label, sizeof label, "%.2g–%.2g", g.bottom, g.top);
        d->AddText(ImVec2(at(g.s, g.top).x + 6, at(g.s, (g.bottom + g.top) / 2).y - 8), text, label);
    }
    const ImU32 lines = e->passes() ? found_colour : blocked_colour;
    for (const glm::dvec2& l : e->extremes) {
        // clipped to the rooms' height, so that a line leaving through the ceiling visibly does
        double a = s0, b = s1;
        const auto hgt = [&](double s) { return l.x + l.y * s; };
        if (std::abs(l.y) > 1e-12)
            for (const double limit : {0.0, e->height}) {
                const double s = (limit - l.x) / l.y;
                if (l.y > 0 ? limit == e->height : limit == 0.0) b = std::min(b, s);
                else a = std::max(a, s);
            }
        if (a < b) d->AddLine(at(a, hgt(a)), at(b, hgt(b)), lines, canvas_px(2));
    }
    const std::string verdict = e->passes()         ? tr("portals.passes")
                                : e->reached >= 2 ? tr("portals.passes_first", {{"reached", std::to_string(e->reached)}})
                                                  : tr("portals.passes_none");
    d->AddText(ImVec2(x + 16, bottom + 4), lines, verdict.c_str());
}

}  // namespace

void portal_plan_canvas(const PvsSession& s, float x, float y, float w, float h) {
    const auto& m = s.view().world->model;
    const bool heights = openings_have_heights(m);
    const float plan_h = heights ? h * 0.55f : h;  // with heights: the elevation under the plan
    const PlanFit f = begin_plan_canvas(m, x, y, w, h, plan_h - legend_height());
    ImDrawList* d = ImGui::GetWindowDrawList();
    pvs_plan(s, d, f);
    if (heights) elevation_canvas(s.view(), d, x, y + plan_h, w, h - plan_h);
    end_plan_canvas(x, y, plan_h, tr("portals.pvs_caption").c_str(), pvs_legend);
}

void portal_plan_canvas(const PortalRenderSession& s, float x, float y, float w, float h, UiActions& out) {
    const PlanFit f = begin_plan_canvas(s.view().world->model, x, y, w, h);
    render_plan(s, ImGui::GetWindowDrawList(), f);
    // drag the eye: the traversal reruns from where it is dropped
    ImGui::SetCursorScreenPos(ImVec2(x, y));
    ImGui::InvisibleButton("plan", ImVec2(w, h));
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    if (ImGui::IsItemActive() && (ImGui::GetIO().MouseDelta.x != 0 || ImGui::GetIO().MouseDelta.y != 0)) {
        const Vec2 p = f.plan(mouse);
        out.move_eye = glm::dvec3(p.x, s.view().camera.eye.y, -p.y);
    }
    end_plan_canvas(x, y, h, tr("portals.render_caption").c_str(), portal_cell_colours::all);
}

// ── [SECTION] the state panels ──────────────────────────────────────────────────────────────────────────────
namespace {

// The PVS matrix with `row` highlighted; only that row when `only_row` (portal_render reads the eye cell's row alone).
void pvs_matrix(const algo::CellModel& m, const std::vector<std::uint8_t>& matrix, std::int32_t row, bool only_row = false) {
    const std::size_t n = m.cells.size();
    if (n > 16) {
        std::size_t set = 0;
        for (std::uint8_t x : matrix) set += x;
        wrapped_text(tr("portals.too_many", {{"cells", std::to_string(n)}, {"set", std::to_string(set)}, {"entries", std::to_string(n * n)}}), dim_text);
        return;
    }
    if (!ImGui::BeginTable("pvs", int(n) + 1, ImGuiTableFlags_Borders | ImGuiTableFlags_SizingFixedFit)) return;
    ImGui::TableSetupColumn("");
    for (const auto& c : m.cells) ImGui::TableSetupColumn(c.name.c_str());
    ImGui::TableHeadersRow();
    for (std::size_t i = 0; i < n; ++i) {
        if (only_row && std::int32_t(i) != row) continue;
        ImGui::TableNextRow();
        if (std::int32_t(i) == row) ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg0, ImGui::GetColorU32(highlight_bg));
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(m.cells[i].name.c_str());
        for (std::size_t j = 0; j < n; ++j) {
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(matrix[i * n + j] ? "1" : " ");
        }
    }
    ImGui::EndTable();
}

void stab_tree(const algo::CellModel& m, const std::vector<algo::StabNode>& tree) {
    // depth of each node from its parent chain; children follow their parent in the list (depth-first order)
    std::vector<int> depth(tree.size(), 0);
    for (std::size_t i = 0; i < tree.size(); ++i) {
        if (tree[i].parent >= 0) depth[i] = depth[std::size_t(tree[i].parent)] + 1;
        ImGui::Text("%*s%s", 3 * depth[i], "", m.cells[tree[i].cell].name.c_str());
        if (i >= 200) {
            ImGui::TextColored(dim_text, "%s", tr("portals.more", {{"more", std::to_string(tree.size() - i - 1)}}).c_str());
            break;
        }
    }
}

}  // namespace

void pvs_state_panel(const PvsSession& s, const PanelLayout& l) {
    begin_column_box(l, Box::state, (tr("portals.pvs_title") + "###state").c_str());
    const PvsView& v = s.view();
    if (ImGui::BeginTabBar("pvs tabs")) {
        if (ImGui::BeginTabItem((tr("portals.matrix_tab") + "###matrix").c_str())) {
            pvs_matrix(v.world->model, v.matrix, v.source);
            ImGui::EndTabItem();
        }
        if (ImGui::BeginTabItem((tr("portals.tree_tab") + "###tree").c_str())) {
            if (v.source >= 0) stab_tree(v.world->model, v.tree);
            ImGui::EndTabItem();
        }
        ImGui::EndTabBar();
    }
    // the count under the matrix: where the column is short, the count is what scrolls, not the matrix's last row
    wrapped_text(tr(v.bounded ? "portals.tests_bounded" : "portals.tests", {{"tests", std::to_string(v.tests)}}), dim_text);
    end_column_box(l, Box::state);
}

void portal_state_panel(const PortalRenderSession& s, bool three_d, const PanelLayout& l, UiActions& out) {
    begin_column_box(l, Box::state, (tr("portals.title") + "###state").c_str());
    const PortalView& v = s.view();
    const auto& m = v.world->model;
    bool show_3d = three_d;
    if (ImGui::Checkbox((tr("portals.walk_3d") + "###3d").c_str(), &show_3d)) out.toggle_3d = true;
    ImGui::SameLine();
    ImGui::TextColored(dim_text, "%s", tr(s.bounding_box_frusta() ? "portals.box_frusta" : "portals.exact_frusta").c_str());
    const auto n = [](std::uint32_t value) { return std::to_string(value); };
    wrapped_text(tr("portals.counts", {{"drawn", n(v.drawn)}, {"back_face", n(v.culled_back_face)}, {"frustum", n(v.culled_frustum)},
                                       {"visits", n(v.visits)}, {"portals", n(v.portals_passed)}}));
    if (ImGui::BeginTabBar("portal tabs")) {
        const std::string matrix_tab = v.eye_cell >= 0 ? tr("portals.row_tab", {{"cell", m.cells[std::size_t(v.eye_cell)].name}}) : tr("portals.matrix_tab");
        if (ImGui::BeginTabItem((matrix_tab + "###matrix").c_str())) {
            pvs_matrix(m, v.world->pvs.matrix, v.eye_cell, v.eye_cell >= 0);
            ImGui::EndTabItem();
        }
        if (ImGui::BeginTabItem((tr("portals.tree_tab") + "###tree").c_str())) {
            if (v.eye_cell >= 0) stab_tree(m, v.world->pvs.trees[std::size_t(v.eye_cell)]);
            ImGui::EndTabItem();
        }
        ImGui::EndTabBar();
    }
    end_column_box(l, Box::state);
}

}  // namespace hsr::viz
