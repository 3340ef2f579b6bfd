// SPDX-License-Identifier: MIT
#include "state/backface_view.h"

#include <algorithm>

#include "analysis/face_visibility.h"
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
    if (faces.size() <= max_faces_cast) {
        const double aspect = camera.aspect > 0.25 && camera.aspect < 4 ? camera.aspect : 1.0;
        const Viewport size{128, std::max(1, int(128 / aspect))};
        const std::vector<std::size_t> seen = analysis::pixels_seen(faces, camera, size);
        for (std::size_t i = 0; i < faces.size(); ++i) v.faces[i].seen = seen[i];
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
                               const bool kept = e.facing == Facing::front;
                               (kept ? v.kept : v.culled) += 1;
                               if (const auto seen = v.faces[i].seen) {
                                   if (kept && *seen == 0) ++v.kept_hidden;
                                   if (!kept && *seen > 0) ++v.culled_seen;
                               }
                               break;
                           }
                   },
                   [&](const CullingFinished&) { v.current = -1; },
               },
               event);
}

std::size_t approx_bytes(const BackfaceView& v) { return sizeof v + v.faces.capacity() * sizeof(FaceView); }

}  // namespace hsr::viz
