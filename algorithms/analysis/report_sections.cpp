// SPDX-License-Identifier: MIT
// The report's one list of families, in its order: each section is defined beside its measurement.
#include "analysis/measurement.h"

namespace hsr::analysis {

std::span<const ReportSection> report_sections() {
    static const std::vector<ReportSection> all{clipping_report, zbuffer_report, hidden_surfaces_report, portals_report,
                                                culling_report, horizon_report, compositing_report, roberts_report,
                                                perspective_report, abuffer_report, intersection_report, complexity_report};
    return all;
}

std::string_view section_title(std::string_view family) {
    for (const ReportSection& s : report_sections())
        for (const auto& [name, title] : s.titles)
            if (name == family) return title;
    return "Other";
}

}  // namespace hsr::analysis
