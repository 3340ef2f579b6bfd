// SPDX-License-Identifier: MIT
// The colours that say what state a thing is in (a box outside the frustum, a cell visited), one table per view,
// each colour with the key of the word its legend shows. They live here, with no GL or ImGui, so that a test can
// check that every pair of a table stays apart for students with each kind of colour blindness
// (tests/state/state_colours_test.cpp simulates them with Machado, Oliveira and Fernandes' 2009 matrices).
// The culling marks are the Okabe–Ito palette's colours; the portal plan's cells are dark fills under light lines.
#pragma once

#include <array>
#include <string_view>

#include "core/okabe_ito.h"

namespace hsr::viz {

struct StateColour {
    std::string_view legend;  // a key of the window's strings: the word beside the swatch
    float r, g, b;            // sRGB, 0–1
};

namespace okabe_ito = algo::okabe_ito;
// A mark in one of the Okabe–Ito colours (core/okabe_ito.h, where the palette is named once).
constexpr StateColour mark(std::string_view legend, okabe_ito::Rgb8 c) {
    return {legend, okabe_ito::unit(c.r), okabe_ito::unit(c.g), okabe_ito::unit(c.b)};
}

namespace culling_colours {  // the hierarchy's boxes, by what happened to them
inline constexpr StateColour outside = mark("culling.mark_outside", okabe_ito::vermillion);
inline constexpr StateColour inside = mark("culling.mark_inside", okabe_ito::bluish_green);
inline constexpr StateColour partial = mark("culling.mark_partial", okabe_ito::yellow);
inline constexpr StateColour too_small = mark("culling.mark_too_small", okabe_ito::blue);
inline constexpr StateColour occluded = mark("culling.mark_occluded", okabe_ito::reddish_purple);
inline constexpr StateColour visible = mark("culling.mark_visible", okabe_ito::sky_blue);
inline constexpr StateColour built{"culling.mark_built", 0.922f, 0.922f, 0.922f};       // white: built, not yet tested
// the view frustum's thin lines
inline constexpr StateColour frustum{"culling.mark_frustum", 0.40f, 0.40f, 0.40f};      // grey
// an occluder's outline and the edges of its occlusion frustum (bold and thin orange lines, not boxes)
inline constexpr StateColour occluder = mark("culling.mark_occluder", okabe_ito::orange);  // orange, as palette::intersection
inline constexpr std::array all{outside, inside, partial, too_small, occluded, visible, built, frustum};
// detail culling alone: a node not below the threshold, its children tested. Yellow as `partial`, whose place it
// takes (a lesson without the frustum test has no node partly inside), so it is not one more colour to tell apart.
inline constexpr StateColour large_enough{"culling.mark_large_enough", partial.r, partial.g, partial.b};
}  // namespace culling_colours

namespace portal_cell_colours {  // the floor plan's cells while portal_render runs (and the PVS's source cell)
inline constexpr StateColour being_drawn{"portals.cell_eye", 0.471f, 0.431f, 0.157f};  // dark yellow: the cell visited now (the PVS: the source)
inline constexpr StateColour visited{"portals.cell_visited", 0.078f, 0.451f, 0.345f};  // dark green
inline constexpr StateColour in_pvs{"portals.cell_in_pvs", 0.275f, 0.322f, 0.408f};    // grey-blue
inline constexpr StateColour out_of_pvs{"portals.cell_out", 0.141f, 0.149f, 0.169f};   // nearly the background
inline constexpr std::array all{being_drawn, visited, in_pvs, out_of_pvs};
}  // namespace portal_cell_colours

namespace intersection_colours {  // IntersectionTest's volumes, by what the ray found in them
inline constexpr StateColour at_work = mark("intersection.mark_at_work", okabe_ito::yellow);  // yellow: the volume being tested
inline constexpr StateColour met = mark("intersection.mark_met", okabe_ito::bluish_green);  // bluish green: met, a hit below
inline constexpr StateColour missed = mark("intersection.mark_missed", okabe_ito::blue);  // blue: missed, all inside it pruned
inline constexpr StateColour false_alarm = mark("intersection.mark_alarm", okabe_ito::orange);  // orange: met, nothing met inside
inline constexpr std::array all{at_work, met, missed, false_alarm};
}  // namespace intersection_colours

namespace backface_colours {  // back-face culling's faces, by the test's verdict (not the scene's colours: they would clash)
inline constexpr StateColour kept = mark("backface.mark_kept", okabe_ito::bluish_green);  // bluish green fill, as the table's word
inline constexpr StateColour under_test = mark("backface.mark_under_test", okabe_ito::yellow);  // yellow, as palette::current_edge
inline constexpr StateColour culled = mark("backface.mark_culled", okabe_ito::vermillion);  // vermillion outline, dark fill
inline constexpr StateColour culled_seen = mark("backface.mark_culled_seen", okabe_ito::reddish_purple);  // reddish purple: culled, yet the ray cast saw it
inline constexpr std::array all{kept, under_test, culled, culled_seen};
}  // namespace backface_colours

namespace zmerge_colours {  // the frames round the pixel merged last
inline constexpr StateColour nearer = mark("zmerge.mark_nearer", okabe_ito::bluish_green);  // bluish green: where the merged value came from
inline constexpr StateColour farther = mark("zmerge.mark_farther", okabe_ito::vermillion);  // vermillion: the part that lost there
inline constexpr std::array all{nearer, farther};
}  // namespace zmerge_colours

namespace transform_colours {  // the perspective transform's view: what a point's or a line's colour says
inline constexpr StateColour compared = mark("transform.mark_compared", okabe_ito::yellow);  // yellow, as palette::current_edge
inline constexpr StateColour occluding = mark("transform.mark_occluding", okabe_ito::bluish_green);  // bluish green, as palette::inside
inline constexpr StateColour target_box{"transform.mark_box", 0.55f, 0.57f, 0.62f};    // grey: the canonical box
inline constexpr std::array all{compared, occluding, target_box};
}  // namespace transform_colours

}  // namespace hsr::viz
