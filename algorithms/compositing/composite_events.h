// SPDX-License-Identifier: MIT
// What alpha compositing tells: the layers along the ray, each premultiplied, each "over" back to front (with the
// straight formula beside it) and "under" front to back, the early stop, the two orders compared, associativity
// checked, and the Porter–Duff operators applied to the two nearest layers. Colours are written [r, g, b, α].
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <variant>

#include "core/phrase.h"
#include "scene/scene.h"

namespace hsr::algo {

// A colour with alpha, each in [0, 1]; straight or premultiplied as the name that holds it says.
struct Rgba {
    double r = 0, g = 0, b = 0, a = 0;
    bool operator==(const Rgba&) const = default;
};
double max_difference(Rgba x, Rgba y);  // the largest of the four channels' differences

enum class PorterDuff : std::uint8_t { clear, a, b, over, in, out, atop, xor_, plus };
std::string_view to_string(PorterDuff op);  // "clear", "A", "B", "over", "in", "out", "atop", "xor", "plus"
std::string expression(PorterDuff op);     // as the paper writes it: "clear", "A", "B", "A over B", …

struct LayersFound {
    static constexpr std::string_view kind = "LayersFound";
    std::uint32_t count;  // polygons the ray passes through
    bool operator==(const LayersFound&) const = default;
};
struct LayerPremultiplied {
    static constexpr std::string_view kind = "LayerPremultiplied";
    std::uint32_t layer;  // 0: the nearest
    SceneId id;
    Rgba straight, premultiplied;
    double alpha;
    bool operator==(const LayerPremultiplied&) const = default;
};
// Back to front: C = F over C (premultiplied), and the same step with straight colours and the notes' formula.
struct OverApplied {
    static constexpr std::string_view kind = "OverApplied";
    std::uint32_t layer;
    SceneId id;
    Rgba before, front, after;            // premultiplied
    Rgba straight_before, straight_after;  // the straight formula's
    double alpha;                          // after.a
    bool operator==(const OverApplied&) const = default;
};
// Front to back: C = C over F ("under").
struct UnderApplied {
    static constexpr std::string_view kind = "UnderApplied";
    std::uint32_t layer;
    SceneId id;
    Rgba before, back, after;  // premultiplied
    double alpha;              // after.a
    bool operator==(const UnderApplied&) const = default;
};
struct EarlyStop {
    static constexpr std::string_view kind = "EarlyStop";
    std::uint32_t layer;    // the first layer left out
    double alpha;           // the composite's α when it stopped
    std::uint32_t skipped;  // layers left out
    bool operator==(const EarlyStop&) const = default;
};
struct OrdersCompared {
    static constexpr std::string_view kind = "OrdersCompared";
    Rgba back_to_front, front_to_back;
    double difference;  // the largest channel difference
    bool same;          // within 1e-9 (what the early stop may leave out aside)
    bool operator==(const OrdersCompared&) const = default;
};
// On the three nearest layers F, M, B: (F over M) over B against F over (M over B).
struct AssociativityChecked {
    static constexpr std::string_view kind = "AssociativityChecked";
    Rgba left, right;              // premultiplied "over"
    Rgba naive_left, naive_right;  // the naive blend of straight colours
    double difference, naive_difference;
    bool associative, naive_associative;  // within 1e-9
    bool operator==(const AssociativityChecked&) const = default;
};
struct PorterDuffApplied {
    static constexpr std::string_view kind = "PorterDuffApplied";
    PorterDuff op;
    Rgba a, b;  // premultiplied: the nearest layer and the next
    double fa, fb;
    Rgba result;
    double alpha;  // result.a
    bool operator==(const PorterDuffApplied&) const = default;
};
struct CompositeFinished {
    static constexpr std::string_view kind = "CompositeFinished";
    Rgba colour;    // back to front, premultiplied
    Rgba straight;  // the same, straight
    bool operator==(const CompositeFinished&) const = default;
};

using CompositeEvent = std::variant<LayersFound, LayerPremultiplied, OverApplied, UnderApplied, EarlyStop, OrdersCompared,
                                    AssociativityChecked, PorterDuffApplied, CompositeFinished>;

// "(0.5, 0.25, 0, 0.5)"
std::string format_rgba(Rgba c);

// What an event says, as a template with named values (core/phrase.h), and in English.
Phrase phrase(const CompositeEvent& e);
std::string describe(const CompositeEvent& e);
std::span<const Saying> composite_sayings();  // every template the compositing machine says

}  // namespace hsr::algo
