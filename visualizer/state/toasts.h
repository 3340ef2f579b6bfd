// SPDX-License-Identifier: MIT
// Short notes in the window for what happened off screen: an export, a save, a reload, a lesson opened, a
// measurement done. A window started from a menu has no terminal, so what is printed there is also shown here for a
// few seconds.
#pragma once

#include <string>
#include <vector>

namespace hsr::viz {

class Toasts {
public:
    static constexpr double seconds = 4;  // how long a note shows
    static constexpr std::size_t most = 3;  // notes shown at once (the newest)

    void say(std::string text, double now);
    // The notes showing at `now`, oldest first, each with how far it has faded (0 fresh … 1 gone).
    struct Showing {
        std::string text;
        double faded;
    };
    std::vector<Showing> showing(double now) const;
    // When the last note goes (the window stays awake until then); 0 with none.
    double until() const;

private:
    struct Note {
        std::string text;
        double said;
    };
    std::vector<Note> notes_;
};

// Seconds on a steady clock (the toasts' time in the window).
double seconds_now();

}  // namespace hsr::viz
