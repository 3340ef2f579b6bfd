// SPDX-License-Identifier: MIT
// Every numeric option at and past its range, and NaN: refused as a usage error (exit 2) naming the option and the
// range in plain numbers, never wrapped ("-5" as 18446744073709551611) or rounded to the largest. And OBJ faces of 3
// to 10^5 vertices (tinyobjloader's own count stops at 255): read whole, or a bad one named with its line.
#include <cmath>
#include <cstdio>

#include "catalogue.h"

namespace bad_inputs {
namespace {

// A regular n-gon on the unit circle as one face.
std::string ngon(std::size_t n) {
    std::string obj;
    for (std::size_t k = 0; k < n; ++k) {
        const double a = 2 * M_PI * double(k) / double(n);
        char line[80];
        std::snprintf(line, sizeof line, "v %.17g %.17g 0\n", std::cos(a), std::sin(a));
        obj += line;
    }
    obj += "f";
    for (std::size_t k = 1; k <= n; ++k) obj += " " + std::to_string(k);
    return obj + "\n";
}

}  // namespace

std::vector<Case> option_cases() {
    std::vector<Case> cs;
    struct Option {
        std::vector<std::string> before;  // the command up to the option
        std::string option, range;
        std::vector<std::string> refused, accepted;
        std::vector<std::string> after;   // what follows the value
    };
    const std::vector<std::string> window{"s.toml"}, shot{"--screenshot", "w.png", "--size", "640x400"};
    const std::vector<Option> options{
        {window, "--frames", "from 1 to 1000000", {"0", "-1", "1000001", "nan", "1e3", "2.5", ""}, {"1"}, shot},
        {window, "--from", "from 0 to 100000000", {"-5", "100000001", "nan", "18446744073709551616"}, {}, {"--gif", "g.gif"}},
        {window, "--to", "from 0 to 100000000", {"-1", "1e9", "nan"}, {}, {"--gif", "g.gif"}},
        {window, "--scale", "from 0.5 to 4", {"nan", "inf", "-inf", "0.49", "4.01", "-1", "1x"}, {"0.5", "4"}, shot},
        {{"practice", "bsp"}, "--seed", "from 0 to 18446744073709551615",
         {"-1", "18446744073709551616", "99999999999999999999999", "nan", "1.5", "0x10"}, {"0", "18446744073709551615"}, {"--count", "1"}},
        {{"practice", "bsp"}, "--count", "from 1 to 1000000", {"0", "-1", "1000001", "nan", "1e3"}, {"1"}, {}},
        {{"practice", "bsp"}, "--level", "from 1 to 3", {"0", "4", "-1", "nan", "2.5"}, {"1", "3"}, {"--count", "1"}},
        {{"report", "--quick", "--out", "r"}, "--repeats", "from 1 to 1000", {"0", "-1", "1001", "nan", "1e308"}, {}, {}}};
    for (const Option& o : options) {
        for (const bool accept : {false, true})
            for (const std::string& value : accept ? o.accepted : o.refused) {
                std::vector<std::string> args = o.before;
                args.push_back(o.option);
                args.push_back(value);
                args.insert(args.end(), o.after.begin(), o.after.end());
                std::string name = "option:";
                for (const std::string& a : args) name += " " + a;
                Case c{name, {{"s.toml", scene}}, {}, {}};
                if (accept) c.runs.push_back({args, 0, {}});
                else c.runs.push_back({args, 2, {o.option, o.range}, o.after.size() > 1 && o.after[1] == "g.gif" ? "g.gif" : "w.png"});
                cs.push_back(c);
            }
    }
    // OBJ faces of 3 to 10^5 vertices: check and render read every vertex (check's machine stops at its event bound
    // on 10^5, and says so)
    for (const std::size_t n : {3, 255, 256, 257, 300, 400, 511, 512, 100000}) {
        Case c{"mesh: one face of " + std::to_string(n) + " vertices", {{"s.toml", mesh_scene}, {"m.obj", ngon(n)}}, {}, {}};
        if (n < 100000) c.runs.push_back({{"check", "s.toml"}, 0, {"ok"}});
        else c.runs.push_back({{"check", "s.toml"}, 1, {"did not finish within"}});
        c.runs.push_back({{"render", "s.toml", "--out", "o.png", "--size", "64x48"}, 0, {"wrote o.png"}});
        cs.push_back(c);
    }
    cs.push_back(bad_mesh("mesh: a face of 300 vertices naming vertex 999", ngon(300) + "f 1 2 999\n",
                          {"m.obj: line 302: face 2 names vertex 999, but the file has 300 vertices"}));
    cs.push_back(bad_mesh("mesh: a face of 1000 vertices, one of them past the list", ngon(999) + "f 1 2 3\n" + "f " + [] {
        std::string f;
        for (int k = 1; k <= 1000; ++k) f += std::to_string(k) + " ";
        return f;
    }() + "\n", {"m.obj: line 1002: face 3 names vertex 1000, but the file has 999 vertices"}));
    // Limits counted as a person counts: characters, not bytes (4,000 CJK characters are 12,000 bytes)
    std::string cjk;
    for (int k = 0; k < 4000; ++k) cjk += "\u6f22";
    cs.push_back(Case{"a lesson title of 4,000 CJK characters", {{"s.toml", scene}, {"l.toml", with(lesson, "title =", "title = \"" + cjk + "\"")}}, {},
                      {{{"check", "l.toml"}, 0, {"ok    l.toml"}}}});
    cs.push_back(Case{"a lesson title of 4,001 CJK characters", {{"s.toml", scene}, {"l.toml", with(lesson, "title =", "title = \"" + cjk + "\u6f22\"")}}, {},
                      {{{"check", "l.toml"}, 1, {"a text of 4001 characters; texts are at most 4000"}}}});
    // A file name is one line: a line feed or a tab in it is shown as \x0a, \x09
    Run newline{{"check", "a\nb.toml"}, 1, {"a\\x0ab.toml"}};
    newline.never_says = {"a\nb.toml"};
    cs.push_back(Case{"a line feed in a file name", {{"s.toml", scene}}, {}, {newline}});
    Run tab{{"render", "s.toml", "--out", "o\t.png", "--size", "64x48"}, 0, {"wrote o\\x09.png"}};
    cs.push_back(Case{"a tab in an output's name", {{"s.toml", scene}}, {}, {tab}});
    // render draws polygons: a terrain is refused with the reason, not an empty picture with exit 0
    cs.push_back(Case{"render of a terrain", {{"t.toml", read(fs::path(HSR_SOURCE_DIR) / "assets/scenes/terrain_ridge.toml")}}, {},
                      {{{"render", "t.toml", "--out", "o.png", "--size", "64x48"}, 1, {"t.toml: render draws polygons"}, "o.png"}}});
    return cs;
}

}  // namespace bad_inputs
