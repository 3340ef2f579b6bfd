// SPDX-License-Identifier: MIT
// A machine's pseudocode as the lecture prints it: one row per line, each row naming the events that light it and
// whether each of them is a Step (→) or a Micro-step (Shift+→). This is the "table beside each view" of DESIGN.md:
// inserting a line changes one row, and the line an event lights is looked up, never counted.
//
//   const Pseudocode<ClipEvent> cohen_sutherland = {
//       {"CS_Clip_3D ( vertex p1, p2 )", {step<SegmentStarted>()}},
//       {"  c1 = mkcode (p1);    c2 = mkcode (p2);", {micro<OutcodeComputed>()}},
//       {"    if outside (R, p1) ...", {step<EdgeClassified>([](const EdgeClassified& e) { return e.closes; })}},
//   };
#pragma once

#include <cstdint>
#include <functional>
#include <initializer_list>
#include <optional>
#include <span>
#include <string_view>
#include <variant>
#include <vector>

namespace hsr::viz {

enum class Stride : std::uint8_t { step, micro };

// An event that lights a line: of one kind, and (where `when` is given) only with these fields.
template <class Event>
struct Light {
    std::string_view kind;
    Stride stride;
    std::function<bool(const Event&)> matches;
};

// step<E>() / micro<E>(when): a light for any event variant that holds E.
template <class E>
struct LightOf {
    Stride stride;
    std::function<bool(const E&)> when;
    template <class Event>
    operator Light<Event>() const {  // NOLINT: converts where the table's event type is known
        return {E::kind, stride, [when = when](const Event& e) {
                    const E* x = std::get_if<E>(&e);
                    return x && (!when || when(*x));
                }};
    }
};
template <class E>
LightOf<E> step(std::function<bool(const E&)> when = {}) {
    return {Stride::step, std::move(when)};
}
template <class E>
LightOf<E> micro(std::function<bool(const E&)> when = {}) {
    return {Stride::micro, std::move(when)};
}

template <class Event>
struct PseudocodeLine {
    std::string_view text;
    std::vector<Light<Event>> lit_by;  // empty: a line no event lights ("{", a declaration)
};

template <class Event>
class Pseudocode {
public:
    Pseudocode(std::initializer_list<PseudocodeLine<Event>> lines) : lines_(lines) {
        for (const auto& l : lines_) text_.push_back(l.text);
    }
    std::span<const std::string_view> text() const { return text_; }

    // The first line the event lights; −1 when no line of this table names it.
    int line_of(const Event& e) const {
        for (std::size_t i = 0; i < lines_.size(); ++i)
            if (find(lines_[i], e)) return int(i);
        return -1;
    }
    // Whether the event is a Step; nullopt when no line of this table names it.
    std::optional<bool> is_major(const Event& e) const {
        for (const auto& l : lines_)
            if (const Light<Event>* light = find(l, e)) return light->stride == Stride::step;
        return std::nullopt;
    }
    // Every event kind some line names (a kind may light several lines, by its fields).
    std::vector<std::string_view> kinds() const {
        std::vector<std::string_view> k;
        for (const auto& l : lines_)
            for (const auto& light : l.lit_by) k.push_back(light.kind);
        return k;
    }

private:
    static const Light<Event>* find(const PseudocodeLine<Event>& l, const Event& e) {
        for (const auto& light : l.lit_by)
            if (light.matches(e)) return &light;
        return nullptr;
    }
    std::vector<PseudocodeLine<Event>> lines_;
    std::vector<std::string_view> text_;
};

}  // namespace hsr::viz
