// SPDX-License-Identifier: MIT
// An A-buffer lesson: the polygons scanned into per-pixel fragment lists with coverage masks, then each list
// resolved front to back into an antialiased, composited pixel; beside it the same image with one sample per pixel.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "abuffer/a_buffer.h"
#include "state/family_facts.h"
#include "state/session.h"

namespace hsr::viz {

// What never changes while a lesson plays.
struct ABufferInput {
    algo::Viewport viewport;
    int mask_size = 4;
    std::vector<algo::ScreenPolygon> polygons;  // the scene's, on the screen (for outlines), by scene index
    std::vector<double> opacities;              // the scene's, by index
    std::vector<glm::dvec4> one_sample;          // the image with one sample per pixel (mask 1: the z-buffer's coverage)
};

struct ABufferView {
    std::shared_ptr<const ABufferInput> input;
    std::vector<std::vector<algo::Fragment>> lists;  // per pixel, as made; nearest first once resolved
    std::vector<glm::dvec4> rgba;                    // per pixel, once resolved
    std::vector<char> resolved;
    int x = -1, y = -1;       // the pixel the last event was at
    int polygon = -1;         // the polygon being scanned
    std::optional<algo::FragmentMade> made;          // the fragment just made
    std::optional<algo::FragmentResolved> fragment;  // the fragment just resolved
    std::optional<algo::PixelResolved> pixel;        // the pixel just resolved
    std::uint64_t fragments = 0;
    std::uint32_t pixels_resolved = 0;
    bool done = false;
    std::size_t at(int px, int py) const { return std::size_t(py) * std::size_t(input->viewport.width) + std::size_t(px); }
};

ABufferView abuffer_initial_view(const algo::Scene& scene, algo::Viewport viewport, int mask_size);
void reduce(ABufferView& view, const algo::ABufferEvent& event);
std::size_t approx_bytes(const ABufferView& view);

class ABufferSession : public PlayerSession<algo::ABufferEvent, algo::ABufferImage, ABufferView> {
public:
    explicit ABufferSession(Lesson lesson, PlayerOptions options = {});
    static RunType machine(const Lesson& lesson);  // the lesson's machine and the view it starts from
    static const FamilyFacts facts;  // for the presets and the report
    static bool plays(algo::ABufferMachine) { return true; }  // every ABufferMachine (state/family_contract.h)
    static std::string sentence_of(const algo::ABufferEvent& e, const ABufferView& view);  // describe(e)

private:
    std::string describe_event(const algo::ABufferEvent& e) const override;
    std::string speak_event(const algo::ABufferEvent& e) const override;
    const Pseudocode<algo::ABufferEvent>& table() const override;
};

}  // namespace hsr::viz
