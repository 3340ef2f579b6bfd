// SPDX-License-Identifier: MIT
#include "depth_sort/front_to_back.h"


namespace hsr::algo {

Steps<FrontToBackEvent, FrontToBackResult> display_front_to_back(std::vector<SortPolygon> polygons, std::vector<std::uint32_t> order,
                                                                 Viewport viewport, Color background) {
    FrontToBackResult out{Image(viewport.width, viewport.height, background), 0, 0};
    std::vector<std::uint8_t> written(std::size_t(viewport.width) * std::size_t(viewport.height), 0);
    std::uint32_t unwritten = std::uint32_t(written.size());
    for (std::size_t k = order.size(); k-- > 0;) {
        if (unwritten == 0) {  // every pixel written: the rest of the list is hidden
            out.left = std::uint32_t(k + 1);
            co_yield ScreenFilled{out.drawn, out.left};
            co_return out;
        }
        const SortPolygon& p = polygons[order[k]];
        std::vector<glm::dvec4> ndc;
        for (const Vec3& v : p.vertices) ndc.emplace_back(v, 1.0);
        const ScreenPolygon s = project_polygon(p.id, p.color, std::move(ndc), viewport);
        FrontPolygonDrawn e{order[k], p.id, 0, 0, 0};
        for (int y = s.row_begin; y < s.row_end; ++y) {
            const Span span = span_on_row(s, y, viewport);
            for (int x = span.begin; x < span.end; ++x) {
                const std::size_t at = std::size_t(y) * std::size_t(viewport.width) + std::size_t(x);
                if (written[at]) {
                    ++e.hidden;
                    continue;
                }
                written[at] = 1, ++e.written, --unwritten;
                out.image.ids[at] = p.id;
                out.image.rgb[3 * at] = p.color.r, out.image.rgb[3 * at + 1] = p.color.g, out.image.rgb[3 * at + 2] = p.color.b;
            }
        }
        ++out.drawn;
        e.unwritten = unwritten;
        co_yield e;
    }
    co_yield FrontDisplayFinished{out.drawn, unwritten};
    co_return out;
}

Phrase phrase(const FrontToBackEvent& event) {
    return std::visit([](const auto& e) { return phrase(DepthSortEvent{e}); }, event);
}

std::string describe(const FrontToBackEvent& event) { return phrase(event).english(); }

}  // namespace hsr::algo
