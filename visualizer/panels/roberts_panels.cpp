// SPDX-License-Identifier: MIT
#include "panels/roberts_panels.h"

#include <string>

#include <imgui.h>

#include "core/events.h"
#include "panels/panel_style.h"
#include "panels/wrapped_text.h"
#include "state/strings.h"

namespace hsr::viz {

void roberts_state_panel(const RobertsSession& s, const PanelLayout& l) {
    begin_column_box(l, Box::state, (tr("roberts.title") + "###state").c_str());
    const RobertsView& v = s.view();
    const auto n = [](auto value) { return std::to_string(value); };
    const auto f = [](double value) { return algo::format_number(value); };
    if (v.edge >= 0) {
        const algo::BodyEdge& e = v.input->edges[std::size_t(v.edge)];
        wrapped_text(tr("roberts.edge", {{"edge", n(v.edge)}, {"body", n(e.body)}}));
        if (v.last_test && int(v.last_test->edge) == v.edge && v.by >= 0)
            wrapped_text(v.last_test->hides ? tr("roberts.hides", {{"by", n(v.by)}, {"t0", f(v.last_test->t0)}, {"t1", f(v.last_test->t1)}})
                                            : tr("roberts.clear", {{"by", n(v.by)}}));
        if (v.edges[std::size_t(v.edge)].removed) wrapped_text(tr("roberts.removed"));
    }
    wrapped_text(tr("roberts.counts", {{"bodies", n(v.input->bodies.size())}, {"edges", n(v.input->edges.size())},
                                       {"removed", n(v.removed)}, {"tests", n(v.tests)}}));
    wrapped_text(tr("roberts.legend"), dim_text);
    // the rule last: where the column is short, it is what scrolls, not the edge under test or the counts
    const float need = column_box_height_so_far();
    wrapped_text(tr("roberts.rule"), dim_text);
    end_column_box(l, Box::state, need);
}

}  // namespace hsr::viz
