// SPDX-License-Identifier: MIT
#include "state/backface_view.h"

#include "core/overloaded.h"

namespace hsr::viz {

using namespace hsr::algo;

BackfaceView initial_view(const std::vector<Face>& faces, const Camera& camera, BackfaceTest test) {
    BackfaceView v;
    v.test = test;
    v.eye = camera.eye;
    for (const Face& f : faces) {
        Plane p;
        plane_of(f.vertices, p);
        v.faces.push_back({f.id, std::make_shared<const std::vector<Vec3>>(f.vertices), p});
    }
    return v;
}

void reduce(BackfaceView& v, const CullEvent& event) {
    std::visit(overloaded{
                   [&](const FaceTested& e) {
                       for (std::size_t i = std::size_t(v.current + 1); i < v.faces.size(); ++i)
                           if (v.faces[i].id == e.id) {  // faces are tested in order
                               v.current = int(i);
                               v.faces[i].facing = e.facing;
                               v.faces[i].value = e.value;
                               (e.facing == Facing::front ? v.kept : v.culled) += 1;
                               break;
                           }
                   },
                   [&](const CullingFinished&) { v.current = -1; },
               },
               event);
}

std::size_t approx_bytes(const BackfaceView& v) { return sizeof v + v.faces.capacity() * sizeof(FaceView); }

}  // namespace hsr::viz
