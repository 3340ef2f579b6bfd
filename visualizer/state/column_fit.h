// SPDX-License-Identifier: MIT
// The right-hand column sized to what its boxes hold: a box with one line takes one line, the lesson text and the
// narration grow, a table gets the rows it has; only when everything does not fit do the boxes share the height,
// each scrolling inside its share (with its scrollbar visible).
//
// A box says how tall its content was when it is drawn (ImGui lays text out as it draws, so the height is known
// only then), and how much of it must be seen (the narration's current sentence, not the faint ones before it; a
// few lines of pseudocode around the one running); the next frame's column is arranged from that. The state and
// narration boxes, which change at every step, keep their largest height for the lesson, so the boxes do not jump
// up and down as a class steps through it.
#pragma once

#include <array>
#include <string>

namespace hsr::viz {

// Top to bottom.
enum class Box { lesson, pseudocode, state, narration, question };
inline constexpr int box_count = 5;

struct BoxSlot {
    float y = 0, h = 0;
};

// What a box asks for: `need` must be seen, `full` is all of it (0: not drawn); `least`, when set, is what must be
// seen while a question is open (the pseudocode's running line alone: the question is about the picture and the state).
struct BoxAsk {
    float need = 0, full = 0, least = 0;
};

class ColumnFit {
public:
    // Arranges the column of `height` pixels for this frame, from what the boxes asked for when last drawn. `lesson`
    // names what plays: another lesson starts from the default shares again. `result_first`: the lesson's last
    // chapter, or its end: what it built comes before the pseudocode and the narration.
    void arrange(float height, const std::string& lesson, bool result_first = false);
    BoxSlot slot(Box b) const { return slots_[std::size_t(b)]; }
    // Whether this frame's arrangement differs from the last one's, or a box was drawn that had no room in it yet
    // (a screenshot waits until neither: ImGui shows a box's scrollbar a frame after its content outgrew it).
    bool moved() const { return moved_; }
    // What the box's content needed this frame (title bar and padding included).
    void asked(Box b, BoxAsk ask);
    // A box left undrawn this frame because its slot holds not one row (the pseudocode at a lesson's end) keeps what
    // it asked for before: it comes back as it was on the next step back.
    void keep(Box b);
    // Whether the box's slot holds all it asked for when last drawn: then it is drawn without a scrollbar. (ImGui
    // decides on a scrollbar from the last frame's content; one shown for a frame narrows the text, which wraps to
    // more lines and asks for more room, and the box's height would swing between two sizes frame after frame.)
    bool holds(Box b) const { return last_[std::size_t(b)].full > 0 && slots_[std::size_t(b)].h >= last_[std::size_t(b)].full; }

    // The arithmetic of arrange, for tests: the question first (up to 60 % of the column), the lesson's need (up to
    // half of the rest), then every other box's need, then the rest of each box, both shared max–min fairly (the smallest asks met in full, the others splitting what
    // remains equally; while a question is open, the state box's rest comes first: the question is about what it holds);
    // what is left over goes to the state box, else the narration. With `result_first`, the state
    // box's full height (up to what the question, the lesson and the narration's need leave, at least 70 % of it)
    // and then the narration's need come before the pseudocode's comes before the other boxes' needs.
    static std::array<float, box_count> share(const std::array<BoxAsk, box_count>& asks, float height, bool result_first = false);

private:
    std::string lesson_;
    std::array<BoxAsk, box_count> asks_{};    // high-water marks of what each box asked for
    std::array<BoxAsk, box_count> last_{};    // what each box asked for when last drawn
    std::array<bool, box_count> drawn_{};     // asked for this frame
    std::array<bool, box_count> measured_{};  // asked for since the lesson started (else asks_ is a default)
    std::array<BoxSlot, box_count> slots_{};
    bool moved_ = true;
};

}  // namespace hsr::viz
