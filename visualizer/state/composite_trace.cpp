// SPDX-License-Identifier: MIT
// The trace's fields of alpha compositing's events (one JSON object per event: state/trace.h).
#include "state/trace_json.h"

#include "compositing/composite_events.h"

namespace hsr::algo {

inline void to_json(nlohmann::json& j, const Rgba& c) { j = nlohmann::json::array({c.r, c.g, c.b, c.a}); }
inline void to_json(nlohmann::json& j, PorterDuff op) { j = std::string(to_string(op)); }

HSR_TO_JSON(LayersFound, count)
HSR_TO_JSON(LayerPremultiplied, layer, id, straight, premultiplied, alpha)
HSR_TO_JSON(OverApplied, layer, id, before, front, after, straight_before, straight_after, alpha)
HSR_TO_JSON(UnderApplied, layer, id, before, back, after, alpha)
HSR_TO_JSON(EarlyStop, layer, alpha, skipped)
HSR_TO_JSON(OrdersCompared, back_to_front, front_to_back, difference, same)
HSR_TO_JSON(AssociativityChecked, left, right, naive_left, naive_right, difference, naive_difference, associative, naive_associative)
HSR_TO_JSON(PorterDuffApplied, op, a, b, fa, fb, result, alpha)
HSR_TO_JSON(CompositeFinished, colour, straight)

}  // namespace hsr::algo

namespace hsr::viz {
HSR_TRACE_LINES(algo::CompositeEvent)
}  // namespace hsr::viz
