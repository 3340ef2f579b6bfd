// SPDX-License-Identifier: MIT
// A general-forms lesson: the same floor plan through the object-space form (each primitive against every other,
// its visible part found and rendered) and the image-space form (each pixel's projector against every primitive).
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "forms/general_forms.h"
#include "state/family_facts.h"
#include "state/session.h"

namespace hsr::viz {

// What never changes while a lesson plays: the plan's camera and segments, each one's image on the line u.
struct FormsInput {
    algo::PlanCamera camera;
    std::vector<glm::dvec2> a, b;  // the segments' ends, plan (world x, y)
    std::vector<algo::Color> colors;
    std::vector<std::int32_t> ids;
    std::vector<std::optional<algo::PrimitiveImage>> images;  // camera space, clipped to the view
    std::uint32_t pixels = 16;
};

struct FormsView {
    std::shared_ptr<const FormsInput> input;
    bool image_space = false;                      // the second form has begun
    std::optional<std::uint32_t> primitive;        // object space: the primitive whose visible part is sought
    std::optional<algo::PrimitivesCompared> compared;
    std::vector<glm::dvec2> hidden;                // object space: what the comparisons so far hid of it
    std::vector<std::optional<std::vector<glm::dvec2>>> visible;  // per primitive, once found
    std::vector<std::int32_t> object_image, image_image;          // per pixel, the primitive drawn (−1: none)
    std::optional<std::uint32_t> pixel;            // image space: the pixel whose projector is cast
    std::optional<algo::ProjectorTested> tested;
    std::vector<std::pair<std::uint32_t, double>> hits;  // image space: this pixel's hits so far (primitive, depth)
    std::uint64_t comparisons = 0, tests = 0;
    std::optional<algo::FormsFinished> finished;
};

FormsView forms_initial_view(const algo::Scene& scene, std::uint32_t pixels);
void reduce(FormsView& view, const algo::FormsEvent& event);
std::size_t approx_bytes(const FormsView& view);

class FormsSession : public PlayerSession<algo::FormsEvent, algo::FormsResult, FormsView> {
public:
    explicit FormsSession(Lesson lesson, PlayerOptions options = {});
    static RunType machine(const Lesson& lesson);
    static const FamilyFacts facts;
    static bool plays(algo::FormsMachine) { return true; }  // every FormsMachine (state/family_contract.h)
    static std::string sentence_of(const algo::FormsEvent& e, const FormsView& view);

private:
    std::string describe_event(const algo::FormsEvent& e) const override;
    std::string speak_event(const algo::FormsEvent& e) const override;
    const Pseudocode<algo::FormsEvent>& table() const override;
};

}  // namespace hsr::viz
