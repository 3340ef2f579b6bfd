// SPDX-License-Identifier: MIT
// A BSP lesson being played: BuildBSP then DisplayBSP on the lesson's scene, with the lecture's pseudocode.
// The build lesson starts at the first event; the traversal lesson starts where the tree is built.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "state/bsp_view.h"
#include "state/edit_history.h"
#include "state/family_facts.h"
#include "state/session.h"

namespace hsr::viz {

class BspSession : public PlayerSession<algo::BspEvent, std::vector<algo::BspPolygonId>, BspView> {
public:
    explicit BspSession(Lesson lesson, PlayerOptions options = {});
    static RunType machine(const Lesson& lesson);  // the lesson's machine and the view it starts from
    static const FamilyFacts facts;  // for the presets and the report
    static bool plays(algo::BspMachine) { return true; }  // every BspMachine (state/family_contract.h)
    static std::string sentence_of(const algo::BspEvent& e, const BspView& view);  // describe(e), as the view after it names things
    algo::BspMachine kind() const { return kind_; }
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
    // Drive mode of a 2D plan: the eye walks `forward` steps (a fiftieth of the plan's size each) along its heading
    // and turns `left` steps of 5° counter-clockwise, and the machine reruns at once.
    void drive(int forward, int left);
    // Scene editing (2D lessons): move one end of an input segment, and undo / redo such edits. Each reruns the
    // machine from the edited input, keeping the cursor at the same step where that step still exists.
    void move_vertex(std::size_t input, std::size_t vertex, algo::Vec3 to);
    // Adds a segment from a to b (2D lessons) with the next free id; false (and nothing done) when it has no length.
    bool add_segment(algo::Vec3 a, algo::Vec3 b);
    // Deletes an input segment or polygon; false when it is the last one (a tree needs something to split).
    bool delete_input(std::size_t input);
    // From the window's BSP box, each an undoable edit that rebuilds the tree (the cursor stays at its step):
    // DisplayBSP's order; the splitter rule; the insertion order ("order of insertion can affect half-plane
    // extent": the rule "first" takes the inputs as they come), reversed or shuffled by `seed`.
    void set_order(algo::Order order);
    void set_splitter(algo::SplitterRule rule);
    enum class Insertion { reversed, shuffled };
    void reorder_inputs(Insertion how, std::uint64_t seed = 0);
    bool undo();
    bool redo();
    const algo::BspJob& job() const { return job_; }
    // The lesson's scene as edited (its segments or polygons moved where the edits put them; the eye where it is).
    const algo::Scene& edited_scene() const { return edited_; }

private:
    std::string describe_event(const algo::BspEvent& e) const override;
    std::string speak_event(const algo::BspEvent& e) const override;
    const Pseudocode<algo::BspEvent>& table() const override;
    bool is_major(const algo::BspEvent& e) const override;
    algo::BspMachine kind_;
    Stats stats_;
    algo::BspJob job_;
    PlayerOptions options_;
    EditHistory<algo::BspJob> history_;  // earlier and undone inputs
    std::optional<std::pair<std::size_t, std::size_t>> last_moved_;  // the vertex the last edit moved
    algo::Vec3 heading_;  // where the eye looks in a 2D plan (in z = 0); the eye's drags keep it
    void rerun();
    void measure();                  // stats_ of the tree of job_, and edited_
    algo::Scene edited_;
    algo::Scene scene_of_job() const;
    void edit(algo::BspJob edited);  // one undo step, then rerun
};

// The BSP tree box's first line, in the window's language: the whole build's figures once the player has seen it
// built; before that, only what the steps have shown (the totals would answer "how many splits does the build
// make?" while it is being asked).
std::string tree_summary(const BspSession& s);

}  // namespace hsr::viz
