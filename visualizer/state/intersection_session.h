// SPDX-License-Identifier: MIT
// An intersection-test lesson: the scene's rays (its segments) one after another through IntersectionTest(root) over
// a hierarchy of the lesson's bounding volume; each model entered, each volume and primitive tested, each false alarm.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "state/family_facts.h"
#include "state/session.h"
#include "volumes/intersection_test.h"

namespace hsr::viz {

struct IntersectionInput {
    algo::BoundingModel model;
    std::vector<algo::Ray> rays;
};

// What a node has been for the ray under test.
enum class CallMark : std::uint8_t { untouched, entered, inside, missed, hit, false_alarm, skipped };

struct IntersectionView {
    std::shared_ptr<const IntersectionInput> input;
    std::optional<std::uint32_t> ray;
    std::vector<std::uint32_t> calls;  // the call stack of IntersectionTest: the root first, the node at work last
    std::vector<CallMark> marks;       // per node, for the ray under test
    std::optional<algo::VolumeTested> volume;
    std::optional<algo::PrimitiveHitTested> primitive;
    std::optional<algo::Vec3> hit_point;  // the hit that answered the ray
    std::vector<std::optional<bool>> answers;  // per ray
    std::uint64_t volume_tests = 0, primitive_tests = 0, false_alarms = 0;
    std::optional<algo::IntersectionFinished> finished;
};

algo::BoundingOptions bounding_options(const Lesson& lesson);
IntersectionView intersection_initial_view(const algo::Scene& scene, algo::BoundingOptions options);
void reduce(IntersectionView& view, const algo::IntersectionEvent& event);
std::size_t approx_bytes(const IntersectionView& view);

class IntersectionSession : public PlayerSession<algo::IntersectionEvent, algo::IntersectionResult, IntersectionView> {
public:
    explicit IntersectionSession(Lesson lesson, PlayerOptions options = {});
    static RunType machine(const Lesson& lesson);
    static const FamilyFacts facts;
    static bool plays(algo::IntersectionMachine) { return true; }  // every IntersectionMachine (state/family_contract.h)
    static std::string sentence_of(const algo::IntersectionEvent& e, const IntersectionView& view);

private:
    std::string describe_event(const algo::IntersectionEvent& e) const override;
    std::string speak_event(const algo::IntersectionEvent& e) const override;
    const Pseudocode<algo::IntersectionEvent>& table() const override;
};

}  // namespace hsr::viz
