#include "state/family_report.h"

namespace hsr::viz {

std::vector<analysis::Measurement> family_report(const algo::AlgorithmInfo& algorithm, const std::string& scenes_dir) {
    const analysis::ReportOptions o{.quick = true, .repeats = 3, .scenes_dir = scenes_dir};
    switch (algorithm.family) {
        case algo::Family::clipping: return analysis::measure_clipping(o);
        case algo::Family::zbuffer:
        case algo::Family::scanline:
        case algo::Family::zmerge: return analysis::measure_zbuffer(o);
        case algo::Family::bsp:
        case algo::Family::depth_sort:
        case algo::Family::raycast: return analysis::measure_hidden_surfaces(o);
        case algo::Family::portals: return analysis::measure_portals(o);
        case algo::Family::culling:
        case algo::Family::backface: return analysis::measure_culling(o);
    }
    return {};
}

}  // namespace hsr::viz
