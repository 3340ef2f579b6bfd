// SPDX-License-Identifier: MIT
#include "state/toasts.h"

#include <algorithm>
#include <chrono>

namespace hsr::viz {

void Toasts::say(std::string text, double now) {
    std::erase_if(notes_, [&](const Note& n) { return now - n.said >= seconds || n.text == text; });
    notes_.push_back({std::move(text), now});
    if (notes_.size() > most) notes_.erase(notes_.begin(), notes_.end() - std::ptrdiff_t(most));
}

std::vector<Toasts::Showing> Toasts::showing(double now) const {
    std::vector<Showing> out;
    for (const Note& n : notes_)
        if (now - n.said < seconds && now >= n.said) out.push_back({n.text, std::clamp((now - n.said) / seconds, 0.0, 1.0)});
    return out;
}

double Toasts::until() const {
    double last = 0;
    for (const Note& n : notes_) last = std::max(last, n.said + seconds);
    return last;
}

double seconds_now() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace hsr::viz
