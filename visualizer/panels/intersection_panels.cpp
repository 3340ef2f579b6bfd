// SPDX-License-Identifier: MIT
#include "panels/intersection_panels.h"

#include <string>

#include <imgui.h>

#include "panels/panel_style.h"
#include "panels/wrapped_text.h"
#include "state/strings.h"

namespace hsr::viz {

namespace {
std::string n(std::uint64_t value) { return std::to_string(value); }
}  // namespace

std::string volume_title(const algo::BoundingOptions& o) {
    switch (o.volume) {
        case algo::VolumeKind::aabb: return "AABB";
        case algo::VolumeKind::sphere: return tr("intersection.sphere");
        case algo::VolumeKind::obb: return "OBB";
        case algo::VolumeKind::kdop: return std::to_string(o.k) + "-DOP";
        case algo::VolumeKind::hulls: break;
    }
    return tr("intersection.hulls");
}

void intersection_state_panel(const IntersectionSession& s, const PanelLayout& l) {
    begin_column_box(l, Box::state, (tr("intersection.title") + "###state").c_str());
    const IntersectionView& v = s.view();
    const algo::BoundingModel& m = v.input->model;
    wrapped_text(tr("intersection.volume", {{"volume", volume_title(m.options)}, {"nodes", n(m.tree.nodes.size())},
                                            {"bottom", n(m.options.max_primitives)}}));
    if (v.ray && !v.calls.empty()) {  // the calls on the stack now (none once the ray is answered)
        std::string path;
        for (const std::uint32_t node : v.calls) path += (path.empty() ? "" : " → ") + n(node);
        wrapped_text(tr("intersection.calls", {{"ray", n(*v.ray)}, {"path", path}}));
    }
    wrapped_text(tr("intersection.counts", {{"volumes", n(v.volume_tests)}, {"primitives", n(v.primitive_tests)}, {"alarms", n(v.false_alarms)}}));
    std::string answers;  // one line for the rays answered so far, a whole clause each
    for (std::size_t r = 0; r < v.answers.size(); ++r)
        if (v.answers[r]) answers += (answers.empty() ? "" : " · ") + tr(*v.answers[r] ? "intersection.ray_hit" : "intersection.ray_miss", {{"ray", n(r)}});
    if (!answers.empty()) wrapped_text(answers);
    const float need = column_box_height_so_far();  // the rays answered are the result: seen whole
    if (answers.empty()) wrapped_text(tr("intersection.legend"), dim_text);  // the rule, until the chapters have shown it at work
    end_column_box(l, Box::state, need);
}

}  // namespace hsr::viz
