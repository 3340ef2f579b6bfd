// SPDX-License-Identifier: MIT
#include "state/bsp_view.h"

#include <memory>

#include "core/overloaded.h"

namespace hsr::viz {

using namespace hsr::algo;

BspView initial_view(const BspJob& job) {
    BspView v;
    v.eye = job.eye.at;
    v.order = job.order;
    for (const BspInput& p : job.polygons) {
        v.polygons.push_back({p.id, std::to_string(p.id), std::make_shared<const std::vector<Vec3>>(p.vertices)});
        v.two_d = v.two_d || p.vertices.size() == 2;
    }
    return v;
}

namespace {

void clear_sides(BspView& v) {
    for (BspPolygonId p : v.sided)
        if (std::size_t(p) < v.polygons.size()) v.polygons[std::size_t(p)].side.reset();
    v.sided.clear();
}

}  // namespace

void reduce(BspView& v, const BspEvent& event) {
    const auto polygon = [&](BspPolygonId p) -> BspPolygonView& { return v.polygons[std::size_t(p)]; };
    const auto give_side = [&](BspPolygonId p, PolygonSide side) {
        polygon(p).side = side;
        v.sided.push_back(p);
    };
    std::visit(overloaded{
                   [&](const BuildStarted&) {},
                   [&](const CandidateScored& e) { v.current_polygon = e.candidate; },
                   [&](const SplitterChosen& e) {
                       v.nodes.resize(std::max<std::size_t>(v.nodes.size(), std::size_t(e.node) + 1));
                       BspNodeView& n = v.nodes[std::size_t(e.node)];
                       n.plane = e.plane;
                       n.parent = e.parent;
                       n.side_of_parent = e.side;
                       n.depth = int(e.depth);
                       n.splitter = e.splitter;
                       if (e.parent >= 0)
                           (e.side == Side::back ? v.nodes[std::size_t(e.parent)].back
                                                 : v.nodes[std::size_t(e.parent)].front) = e.node;
                       v.depth = std::max(v.depth, int(e.depth) + 1);
                       v.current_node = e.node;
                       v.current_polygon = e.splitter;
                       polygon(e.splitter).node = e.node;
                       clear_sides(v);
                   },
                   [&](const PolygonClassified& e) {
                       v.current_polygon = e.polygon;
                       give_side(e.polygon, e.side);
                       if (e.side == PolygonSide::coplanar) polygon(e.polygon).node = e.node;
                   },
                   [&](const PolygonSplit& e) {
                       polygon(e.polygon).replaced = true;
                       give_side(e.polygon, PolygonSide::spanning);
                       // copies, not references: the resize below may move the polygons
                       const std::int32_t source = polygon(e.polygon).source;
                       const std::string label = polygon(e.polygon).label;
                       v.polygons.resize(std::max<std::size_t>(v.polygons.size(), std::size_t(e.back_part) + 1));
                       v.polygons[std::size_t(e.front_part)] = {source, label + "f", e.front, false, -1,
                                                                PolygonSide::front, 0};
                       v.polygons[std::size_t(e.back_part)] = {source, label + "b", e.back, false, -1,
                                                               PolygonSide::back, 0};
                       v.sided.push_back(e.front_part);
                       v.sided.push_back(e.back_part);
                       ++v.splits;
                       v.current_polygon = e.front_part;
                   },
                   [&](const NodeFinished& e) { v.current_node = e.node; },
                   [&](const BuildFinished&) {
                       v.built = true;
                       v.current_node = v.current_polygon = -1;
                       clear_sides(v);
                   },
                   [&](const EyeClassified& e) {
                       v.current_node = e.node;
                       v.order = e.order;
                       v.nodes[std::size_t(e.node)].eye_side = e.side;
                   },
                   [&](const PolygonDrawn& e) {
                       v.current_node = e.node;
                       v.current_polygon = e.polygon;
                       polygon(e.polygon).drawn = int(e.order);
                       v.drawn = int(e.order);
                   },
                   [&](const TraversalFinished&) { v.current_node = v.current_polygon = -1; },
                   [&](const BspBoundReached&) { v.bounded = true; },
               },
               event);
}

std::size_t approx_bytes(const BspView& v) {
    std::size_t b = sizeof v + v.nodes.capacity() * sizeof(BspNodeView) + v.sided.capacity() * sizeof(algo::BspPolygonId);
    for (const auto& p : v.polygons) b += sizeof p + p.label.capacity();
    return b;
}

algo::PolygonNamer namer(const BspView& v) {
    return [&v](BspPolygonId p) {
        return p >= 0 && std::size_t(p) < v.polygons.size() ? v.polygons[std::size_t(p)].label : "#" + std::to_string(p);
    };
}

std::vector<std::string> labels(const BspView& v) {
    std::vector<std::string> out;
    for (const auto& p : v.polygons) out.push_back(p.label);
    return out;
}

}  // namespace hsr::viz
