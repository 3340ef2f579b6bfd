#include "state/session.h"

#include "state/bsp_session.h"
#include "state/clip_session.h"
#include "state/cull_session.h"
#include "state/culling_session.h"
#include "state/depth_sort_session.h"
#include "state/portal_session.h"
#include "state/raycast_session.h"
#include "state/scanline_session.h"
#include "state/zbuffer_session.h"
#include "state/zmerge_session.h"

namespace hsr::viz {

std::unique_ptr<Session> make_session(Lesson lesson, PlayerOptions options) {
    switch (lesson.algorithm.family) {
        case algo::Family::clipping: return std::make_unique<ClipSession>(std::move(lesson), options);
        case algo::Family::bsp: return std::make_unique<BspSession>(std::move(lesson), options);
        case algo::Family::backface: return std::make_unique<CullSession>(std::move(lesson), options);
        case algo::Family::zbuffer: return std::make_unique<ZBufferSession>(std::move(lesson), options);
        case algo::Family::raycast: return std::make_unique<RayCastSession>(std::move(lesson), options);
        case algo::Family::scanline: return std::make_unique<ScanLineSession>(std::move(lesson), options);
        case algo::Family::zmerge: return std::make_unique<ZMergeSession>(std::move(lesson), options);
        case algo::Family::depth_sort: return std::make_unique<DepthSortSession>(std::move(lesson), options);
        case algo::Family::culling: return make_culling_session(std::move(lesson), options);
        case algo::Family::portals: {
            const int variant = lesson.algorithm.variant;  // 0 PVS, 1 exact frusta, 2 bounding-box frusta
            if (variant == 0) return std::make_unique<PvsSession>(std::move(lesson), options);
            return std::make_unique<PortalRenderSession>(std::move(lesson), variant == 2, options);
        }
    }
    return nullptr;
}

}  // namespace hsr::viz
