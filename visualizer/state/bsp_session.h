// A BSP lesson being played: BuildBSP then DisplayBSP on the lesson's scene, with the lecture's pseudocode.
// The build lesson starts at the first event; the traversal lesson starts where the tree is built.
#pragma once

#include "state/bsp_view.h"
#include "state/session.h"

namespace hsr::viz {

enum class BspLesson : int { build = 0, traversal = 1 };

class BspSession : public PlayerSession<algo::BspEvent, std::vector<algo::BspPolygonId>, BspView> {
public:
    explicit BspSession(Lesson lesson, PlayerOptions options = {});
    BspLesson kind() const { return kind_; }
    std::span<const std::string_view> pseudocode() const override;
    // Build statistics of the same tree built once more, timed (the player's own run is stepped, not timed).
    struct Stats {
        std::size_t polygons_in = 0, polygons_after = 0, nodes = 0;
        std::uint32_t depth = 0, splits = 0;
        double build_ms = 0;
        algo::SplitterRule rule = algo::SplitterRule::first;
    };
    const Stats& stats() const { return stats_; }
    // Moves the eye and reruns the machine (the build is the same; the traversal follows the new eye), keeping
    // the cursor at the same step. In a 2D scene the eye stays in the plane z = 0.
    void move_eye(algo::Vec3 eye);

private:
    std::string describe_event(const algo::BspEvent& e) const override;
    int line_of(const algo::BspEvent& e) const override;
    bool is_major(const algo::BspEvent& e) const override;
    BspLesson kind_;
    Stats stats_;
    algo::BspJob job_;
    PlayerOptions options_;
};

}  // namespace hsr::viz
