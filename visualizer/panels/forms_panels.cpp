// SPDX-License-Identifier: MIT
#include "panels/forms_panels.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <imgui.h>

#include "core/events.h"
#include "panels/fat_pixels.h"
#include "panels/panel_style.h"
#include "panels/view_side_box.h"
#include "panels/wrapped_text.h"
#include "state/strings.h"

namespace hsr::viz {

namespace {

const ImU32 yellow = okabe_ito_u32(algo::okabe_ito::yellow), white = IM_COL32(240, 240, 240, 255), red = okabe_ito_u32(algo::okabe_ito::vermillion);
const ImU32 faint = IM_COL32(120, 124, 132, 90), wedge = IM_COL32(160, 164, 172, 200), empty_cell = IM_COL32(40, 43, 50, 255);

std::string n(std::uint64_t value) { return std::to_string(value); }
std::string f(double value) { return algo::format_number(value + 0.0); }

// The plan (world x, y) fitted into a rectangle of the canvas, y up.
struct PlanFit {
    glm::dvec2 centre;
    double scale;
    ImVec2 mid;
    ImVec2 operator()(glm::dvec2 p) const {
        return {mid.x + float((p.x - centre.x) * scale), mid.y - float((p.y - centre.y) * scale)};
    }
};

// Where the projector through u meets the line of a primitive's image (camera space), in the plan.
glm::dvec2 on_primitive(const algo::PlanCamera& c, const algo::PrimitiveImage& im, double u) {
    const glm::dvec2 o = c.projector_origin(u), d = c.projector_direction(u), e = im.b - im.a, w = im.a - o;
    const double det = d.x * e.y - d.y * e.x;
    const double t = det == 0 ? 0 : (w.x * e.y - w.y * e.x) / det;
    return c.to_world(o + t * d);
}

// How far the picture draws the field of view: past the farthest segment end, short of the far line.
double reach(const FormsInput& in) {
    double r = 0;
    for (std::size_t i = 0; i < in.a.size(); ++i)
        r = std::max({r, in.camera.to_camera(in.a[i]).y, in.camera.to_camera(in.b[i]).y});
    return std::min(in.camera.far, std::max(r * 1.1, in.camera.near * 2));
}

// A point of the projector through u at depth z (plan).
glm::dvec2 along(const algo::PlanCamera& c, double u, double z) { return c.to_world(c.projector_origin(u) + z * c.projector_direction(u)); }

void strip(ImDrawList* d, ImVec2 o, float cell, const FormsInput& in, const std::vector<std::int32_t>& image,
           std::optional<std::uint32_t> framed, const std::vector<std::int32_t>* other) {
    for (std::uint32_t k = 0; k < in.pixels; ++k) {
        const ImVec2 a(o.x + float(k) * cell, o.y), b(a.x + cell - 1, a.y + cell - 1);
        d->AddRectFilled(a, b, image[k] < 0 ? empty_cell : rgb(in.colors[std::size_t(image[k])]));
        if (other && (*other)[k] != image[k]) d->AddRect(a, b, red, 0, 0, canvas_px(2));  // the forms disagree here
    }
    if (framed) {
        const ImVec2 a(o.x + float(*framed) * cell - 1, o.y - 1);
        d->AddRect(a, ImVec2(a.x + cell + 1, a.y + cell + 1), yellow, 0, 0, canvas_px(2.5f));
    }
}

}  // namespace

void forms_canvas(const FormsSession& s, float x, float y, float w, float h) {
    const FormsView& v = s.view();
    const FormsInput& in = *v.input;
    const algo::PlanCamera& c = in.camera;
    ImDrawList* d = begin_canvas("##forms canvas", x, y, w, h);
    const float margin = 24, line = ImGui::GetTextLineHeightWithSpacing();
    const float cell = std::clamp((w - 2 * margin) / float(in.pixels), 3.0f, canvas_px(44));
    const float strips = 2 * (line + cell + 6) + line + margin;  // two titled strips and the pixel numbers under them
    const float plan_h = std::max(60.0f, h - strips - 2 * margin);

    // The plan: fit the segments, the eye and the field of view as far as it is drawn.
    const double far_reach = reach(in);
    std::vector<glm::dvec2> pts = {c.eye, along(c, -1, far_reach), along(c, 1, far_reach)};
    if (!c.perspective) pts.push_back(along(c, -1, 0)), pts.push_back(along(c, 1, 0));
    pts.insert(pts.end(), in.a.begin(), in.a.end());
    pts.insert(pts.end(), in.b.begin(), in.b.end());
    glm::dvec2 lo = pts[0], hi = pts[0];
    for (const glm::dvec2 p : pts) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const glm::dvec2 size = glm::max(hi - lo, glm::dvec2(1e-9));
    const PlanFit fit{(lo + hi) / 2.0, std::min(double(w - 2 * margin) / size.x, double(plan_h) / size.y) * 0.96,
                      ImVec2(x + w / 2, y + margin + plan_h / 2)};

    // The field of view, the near line, and every pixel's projector, faint.
    for (const double u : {-1.0, 1.0}) d->AddLine(fit(along(c, u, 0)), fit(along(c, u, far_reach)), wedge, canvas_px(1.5f));
    d->AddLine(fit(along(c, -1, c.near)), fit(along(c, 1, c.near)), wedge, canvas_px(1));
    for (std::uint32_t k = 0; k < in.pixels; ++k) {
        const double u = c.pixel_centre(k, in.pixels);
        d->AddLine(fit(along(c, u, c.near)), fit(along(c, u, far_reach)), faint, 1);
    }
    // each projector's pixel number past its far end, as the image row below numbers them (the questions say "follow
    // pixel 12's projector"): every one when they are far enough apart for two digits, else every 2nd or 5th
    if (in.pixels >= 2) {
        ImFont* font = ImGui::GetFont();
        const float small = axis_number_size();
        const ImVec2 p0 = fit(along(c, c.pixel_centre(0, in.pixels), far_reach)), p1 = fit(along(c, c.pixel_centre(1, in.pixels), far_reach));
        const auto every = std::uint32_t(axis_number_step(std::hypot(p1.x - p0.x, p1.y - p0.y)));
        for (std::uint32_t k = 0; k < in.pixels; k += every) {
            const double u = c.pixel_centre(k, in.pixels);
            const ImVec2 end = fit(along(c, u, far_reach * 1.04));
            const std::string t = std::to_string(k);
            const ImVec2 text = font->CalcTextSizeA(small, 1e9f, 0, t.c_str());
            d->AddText(font, small, ImVec2(end.x - text.x / 2, end.y - text.y / 2), IM_COL32(170, 170, 170, 255), t.c_str());
        }
    }
    // The pixel whose projector is cast, to its closest hit; its hits so far.
    if (v.pixel && !v.finished) {
        const double u = c.pixel_centre(*v.pixel, in.pixels);
        d->AddLine(fit(along(c, u, 0)), fit(along(c, u, far_reach)), yellow, canvas_px(2));
        double nearest = -1;
        for (const auto& [primitive, depth] : v.hits) {
            d->AddCircleFilled(fit(along(c, u, depth)), canvas_px(4), rgb(in.colors[primitive]));
            if (nearest < 0 || depth < nearest) nearest = depth;
        }
        if (nearest >= 0) d->AddCircle(fit(along(c, u, nearest)), canvas_px(7), white, 0, canvas_px(2));
    }

    // The segments: thin until their visible part is found, then that part thick.
    for (std::size_t i = 0; i < in.a.size(); ++i) {
        const bool at_work = v.primitive == i, other = v.compared && v.compared->other == i;
        if (at_work) d->AddLine(fit(in.a[i]), fit(in.b[i]), yellow, canvas_px(9));
        if (other) d->AddLine(fit(in.a[i]), fit(in.b[i]), white, canvas_px(7));
        d->AddLine(fit(in.a[i]), fit(in.b[i]), rgb(in.colors[i], v.visible[i] ? 0.45f : 1), canvas_px(v.visible[i] ? 2 : 4));
        if (v.visible[i] && in.images[i])
            for (const glm::dvec2 part : *v.visible[i])
                d->AddLine(fit(on_primitive(c, *in.images[i], part.x)), fit(on_primitive(c, *in.images[i], part.y)), rgb(in.colors[i]), canvas_px(6));
    }
    for (std::size_t i = 0; i < in.a.size(); ++i) {  // the labels over every line, on a dark ground
        const ImVec2 mid = fit(in.a[i] + (in.b[i] - in.a[i]) / 3.0);  // a third along: walls crossing at their middles keep both labels
        const std::string id = n(std::uint64_t(in.ids[i]));
        const ImVec2 at(mid.x + canvas_px(8), mid.y - line), text = ImGui::CalcTextSize(id.c_str());
        d->AddRectFilled(ImVec2(at.x - 2, at.y), ImVec2(at.x + text.x + 2, at.y + text.y), IM_COL32(26, 28, 33, 220));
        d->AddText(at, white, id.c_str());
    }
    // What the comparisons so far hide of the primitive at work.
    if (v.primitive && in.images[*v.primitive])
        for (const glm::dvec2 part : v.hidden)
            d->AddLine(fit(on_primitive(c, *in.images[*v.primitive], part.x)), fit(on_primitive(c, *in.images[*v.primitive], part.y)), red,
                       canvas_px(5));
    d->AddCircleFilled(fit(c.eye), canvas_px(6), yellow);

    // The two images, one row of pixels each, the pixel numbers under the second.
    const float row_w = cell * float(in.pixels), x0 = x + (w - row_w) / 2;
    float top = y + margin + plan_h + margin / 2;
    d->AddText(ImVec2(x0, top), white, tr("forms.object_strip").c_str());
    top += line;
    strip(d, ImVec2(x0, top), cell, in, v.object_image, std::nullopt, v.finished ? &v.image_image : nullptr);
    top += cell + 6;
    d->AddText(ImVec2(x0, top), white, tr("forms.image_strip").c_str());
    top += line;
    strip(d, ImVec2(x0, top), cell, in, v.image_image, v.finished ? std::nullopt : v.pixel, v.finished ? &v.object_image : nullptr);
    top += cell + 2;
    const float digits = ImGui::CalcTextSize("00").x + 4;
    const std::uint32_t every = std::max(1u, std::uint32_t(std::ceil(digits / cell)));
    for (std::uint32_t k = 0; k < in.pixels; k += every) {
        const std::string t = n(k);
        d->AddText(ImVec2(x0 + (float(k) + 0.5f) * cell - ImGui::CalcTextSize(t.c_str()).x / 2, top), IM_COL32(170, 170, 170, 255), t.c_str());
    }
    ImGui::End();
}

namespace {

// Every segment: its image on the image line and how much of it is visible; with the legend and R's hint.
void segments_table(const FormsView& v) {
    const FormsInput& in = *v.input;
    if (ImGui::BeginTable("segments", 3, ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg)) {
        const std::string segment = tr("forms.segment"), image = tr("forms.image"), visible = tr("forms.visible");
        ImGui::TableSetupColumn(segment.c_str(), ImGuiTableColumnFlags_WidthFixed, ImGui::CalcTextSize(segment.c_str()).x);
        ImGui::TableSetupColumn(image.c_str());
        ImGui::TableSetupColumn(visible.c_str(), ImGuiTableColumnFlags_WidthFixed, ImGui::CalcTextSize(visible.c_str()).x);
        ImGui::TableHeadersRow();
        for (std::size_t i = 0; i < in.ids.size(); ++i) {
            ImGui::TableNextRow();
            if (v.primitive == i) ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg0, ImGui::GetColorU32(highlight_bg));
            ImGui::TableNextColumn();
            ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(rgb(in.colors[i])), "%d", in.ids[i]);
            ImGui::TableNextColumn();
            if (in.images[i]) wrapped_text("[" + f(in.images[i]->from) + ", " + f(in.images[i]->to) + ")");  // at spaces only
            else ImGui::TextUnformatted(tr("forms.not_in_view").c_str());
            ImGui::TableNextColumn();
            if (v.visible[i] && in.images[i]) {
                double length = 0;
                for (const glm::dvec2 p : *v.visible[i]) length += p.y - p.x;
                ImGui::Text("%.0f %%", 100 * length / (in.images[i]->to - in.images[i]->from));
            }
        }
        ImGui::EndTable();
    }
    wrapped_text(tr("forms.legend"), dim_text);
    wrapped_text(tr("forms.report_hint"), dim_text);
}

}  // namespace

void forms_state_panel(const FormsSession& s, bool table_in_view, const PanelLayout& l) {
    begin_column_box(l, Box::state, (tr("forms.title") + "###state").c_str());
    const FormsView& v = s.view();
    const FormsInput& in = *v.input;
    const std::uint64_t P = std::uint64_t(std::count_if(in.images.begin(), in.images.end(), [](const auto& i) { return i.has_value(); }));
    if (v.finished) wrapped_text(tr("forms.phase_done"));
    else if (v.image_space && v.pixel) wrapped_text(tr("forms.phase_image", {{"pixel", n(*v.pixel)}}));
    else if (v.primitive) wrapped_text(tr("forms.phase_object", {{"id", n(std::uint64_t(in.ids[*v.primitive]))}}));
    if (v.finished)  // the totals against the formulas once both forms are done (a lesson asks for them before)
        wrapped_text(tr("forms.counts", {{"comparisons", n(v.comparisons)}, {"tests", n(v.tests)}, {"P", n(P)}, {"p", n(in.pixels)}}));
    else
        wrapped_text(tr("forms.counts_so_far", {{"comparisons", n(v.comparisons)}, {"tests", n(v.tests)}}));
    const float need = column_box_height_so_far();  // the phase and the counts; the table may scroll
    if (v.primitive && !v.hidden.empty()) {
        std::string parts;
        for (const glm::dvec2 h : v.hidden) parts += (parts.empty() ? "[" : ", [") + f(h.x) + ", " + f(h.y) + ")";
        wrapped_text(tr("forms.hidden_so_far", {{"parts", parts}}));
    }
    if (!table_in_view) segments_table(v);
    end_column_box(l, Box::state, need);
}

void forms_table_box(const FormsSession& s, float view_w, float view_h) {
    begin_view_side_box(tr("forms.title") + "###segments in the view", view_w, view_h, 0, forms_table_share);
    segments_table(s.view());
    end_view_side_box();
}

}  // namespace hsr::viz
