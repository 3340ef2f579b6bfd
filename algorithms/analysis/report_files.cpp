// SPDX-License-Identifier: MIT
#include "analysis/report_files.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

#include "scene/load_scene.h"
#include "core/okabe_ito.h"

namespace hsr::analysis {
namespace {

std::string number(double v) {
    char b[32];
    if (v == 0) return "0";
    std::snprintf(b, sizeof b, std::fabs(v) >= 1e-3 && std::fabs(v) < 1e5 ? "%.4g" : "%.3e", v);
    return b;
}

std::string csv_field(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

// A chart's k-th method's colour (Okabe–Ito), as "#rrggbb".
std::string chart_colour(std::size_t k) {
    const algo::okabe_ito::Rgb8 c = algo::okabe_ito::chart[k % algo::okabe_ito::chart.size()];
    char hex[8];
    std::snprintf(hex, sizeof hex, "#%02x%02x%02x", c.r, c.g, c.b);
    return hex;
}

std::string xml_text(const std::string& s) {
    std::string out;
    for (char c : s) out += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : std::string(1, c);
    return out;
}


}  // namespace

std::vector<std::string> families_of(const std::vector<Measurement>& rows) {
    std::vector<std::string> f;
    for (const Measurement& m : rows)
        if (std::find(f.begin(), f.end(), m.family) == f.end()) f.push_back(m.family);
    return f;
}

std::string report_markdown(const std::vector<Measurement>& rows) {
    std::string md;
    for (const std::string& family : families_of(rows)) {
        const auto first = std::find_if(rows.begin(), rows.end(), [&](const Measurement& m) { return m.family == family; });
        const bool sweep = first->size > 0;  // a chart of run time against size, else of error against run time
        md += "## " + std::string(section_title(family)) + "\n\nError: " + first->error_name + ". ![" +
              (sweep ? "run time against size" : "error against run time") + "](" + family + ".svg)\n\n| method | setting | median ms | error | " +
              (first->wrong_name.empty() ? std::string("—") : first->wrong_name) + " | notes |\n|---|---|---:|---:|---:|---|\n";
        for (const Measurement& m : rows) {
            if (m.family != family) continue;
            const std::string wrong = std::to_string(m.wrong) + (m.wrong_must_be_zero ? (m.wrong == 0 ? " (must be 0: ok)" : " (must be 0: VIOLATED)") : "");
            md += "| " + m.method + " | " + m.setting + " | " + number(m.median_ms) + " | " + number(m.error) + " | " + wrong + " | " +
                  m.extra + " |\n";
        }
        md += "\n";
    }
    return md;
}

std::string report_csv(const std::vector<Measurement>& rows) {
    std::string csv = "family,method,setting,median_ms,error,error_name,wrong,wrong_name,wrong_must_be_zero,extra,size\n";
    for (const Measurement& m : rows)
        csv += csv_field(m.family) + "," + csv_field(m.method) + "," + csv_field(m.setting) + "," + number(m.median_ms) + "," +
               number(m.error) + "," + csv_field(m.error_name) + "," + std::to_string(m.wrong) + "," + csv_field(m.wrong_name) + "," +
               (m.wrong_must_be_zero ? "true" : "false") + "," + csv_field(m.extra) + "," + (m.size > 0 ? number(m.size) : "") + "\n";
    return csv;
}

std::vector<ExtremeCase> run_extreme_cases(const std::string& dir) {
    std::vector<std::string> files;
    for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
        if (e.path().extension() == ".toml") files.push_back(e.path().string());
    std::sort(files.begin(), files.end());
    std::vector<ExtremeCase> cases;
    for (const std::string& f : files) {
        ExtremeCase c{std::filesystem::path(f).filename().string(), "", "", {}, ""};
        try {
            const algo::Scene s = algo::load_scene(f);
            c.name = s.name, c.promise = s.promise;
            c.outcomes = check_expectations(s);
        } catch (const std::exception& e) {
            c.load_error = e.what();
        }
        cases.push_back(std::move(c));
    }
    return cases;
}

std::string extreme_markdown(const std::vector<ExtremeCase>& cases) {
    std::size_t kept = 0, all = 0;
    for (const ExtremeCase& c : cases)
        for (const ExpectOutcome& o : c.outcomes) kept += o.passed, ++all;
    std::string md = "## Extreme cases (assets/scenes/extreme)\n\n" + std::to_string(cases.size()) + " cases, " + std::to_string(kept) +
                     " of " + std::to_string(all) + " expectations kept.\n\n";
    for (const ExtremeCase& c : cases) {
        md += "### " + c.name + " (`" + c.file + "`)\n\nPromise: " + c.promise + "\n\n";
        if (!c.load_error.empty()) {
            md += "Not loaded: " + c.load_error + "\n\n";
            continue;
        }
        md += "| expectation | line | outcome | error | found |\n|---|---:|---|---:|---|\n";
        for (const ExpectOutcome& o : c.outcomes)
            md += "| " + o.what + " | " + std::to_string(o.line) + " | " + (o.passed ? "kept" : "BROKEN") + " | " + number(o.error) +
                  " | " + o.detail + " |\n";
        md += "\n";
    }
    return md;
}

std::string error_chart_svg(const std::vector<Measurement>& rows, const std::string& family) {
    std::vector<const Measurement*> pts;
    for (const Measurement& m : rows)
        if (m.family == family) pts.push_back(&m);
    // Axes: log10 of the time and of the error; errors of 0 sit on their own line below the lowest decade.
    double t_lo = 1e300, t_hi = -1e300, e_lo = 1e300, e_hi = -1e300;
    for (const Measurement* m : pts) {
        const double t = std::log10(std::max(m->median_ms, 1e-6));
        t_lo = std::min(t_lo, t), t_hi = std::max(t_hi, t);
        if (m->error > 0) e_lo = std::min(e_lo, std::log10(m->error)), e_hi = std::max(e_hi, std::log10(m->error));
    }
    if (pts.empty()) t_lo = 0, t_hi = 1;
    if (e_lo > e_hi) e_lo = -3, e_hi = 0;
    t_lo = std::floor(t_lo), t_hi = std::max(std::ceil(t_hi), t_lo + 1);
    e_lo = std::floor(e_lo), e_hi = std::max(std::ceil(e_hi), e_lo + 1);
    const double zero_line = e_lo - 1;  // the "0" row

    const int width = 860, height = 440, left = 70, right = 300, top = 40, bottom = 50;
    const auto x_of = [&](double t) { return left + (t - t_lo) / (t_hi - t_lo) * (width - left - right); };
    const auto y_of = [&](double e) { return top + (e_hi - e) / (e_hi - zero_line) * (height - top - bottom); };

    // One colour per method (Okabe–Ito), a legend on the right.
    std::map<std::string, int> colour;
    std::vector<std::string> methods;
    for (const Measurement* m : pts)
        if (colour.emplace(m->method, int(colour.size()) % 8).second) methods.push_back(m->method);

    std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(width) + "\" height=\"" +
                      std::to_string(height) + "\" font-family=\"sans-serif\" font-size=\"12\">\n"
                      "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    svg += "<text x=\"" + std::to_string(left) + "\" y=\"22\" font-size=\"14\">" + xml_text(std::string(section_title(family))) + "</text>\n";
    for (double t = t_lo; t <= t_hi + 1e-9; t += 1) {
        const double x = x_of(t);
        svg += "<line x1=\"" + number(x) + "\" y1=\"" + std::to_string(top) + "\" x2=\"" + number(x) + "\" y2=\"" +
               std::to_string(height - bottom) + "\" stroke=\"#ddd\"/><text x=\"" + number(x) + "\" y=\"" +
               std::to_string(height - bottom + 16) + "\" text-anchor=\"middle\">" + number(std::pow(10.0, t)) + "</text>\n";
    }
    for (double e = zero_line; e <= e_hi + 1e-9; e += 1) {
        const double y = y_of(e);
        svg += "<line x1=\"" + std::to_string(left) + "\" y1=\"" + number(y) + "\" x2=\"" + std::to_string(width - right) + "\" y2=\"" +
               number(y) + "\" stroke=\"#ddd\"/><text x=\"" + std::to_string(left - 6) + "\" y=\"" + number(y + 4) +
               "\" text-anchor=\"end\">" + (e == zero_line ? std::string("0") : "1e" + std::to_string(int(e))) + "</text>\n";
    }
    svg += "<text x=\"" + number((left + width - right) / 2.0) + "\" y=\"" + std::to_string(height - 12) +
           "\" text-anchor=\"middle\">median run time (ms, log)</text>\n";
    svg += "<text transform=\"translate(16," + number((top + height - bottom) / 2.0) + ") rotate(-90)\" text-anchor=\"middle\">error (log)</text>\n";
    for (const Measurement* m : pts) {
        const double x = x_of(std::log10(std::max(m->median_ms, 1e-6)));
        const double y = y_of(m->error > 0 ? std::log10(m->error) : zero_line);
        svg += "<g><title>" + xml_text(m->method + ", " + m->setting) + "</title><circle cx=\"" + number(x) + "\" cy=\"" +
               number(y) + "\" r=\"5\" fill=\"" + chart_colour(std::size_t(colour[m->method])) + "\" stroke=\"black\" stroke-width=\"0.5\"/></g>\n";
    }
    for (std::size_t k = 0; k < methods.size(); ++k) {
        const int y = top + 8 + int(k) * 18;
        svg += "<circle cx=\"" + std::to_string(width - right + 20) + "\" cy=\"" + std::to_string(y) + "\" r=\"5\" fill=\"" +
               chart_colour(std::size_t(colour[methods[k]])) + "\" stroke=\"black\" stroke-width=\"0.5\"/><text x=\"" + std::to_string(width - right + 30) +
               "\" y=\"" + std::to_string(y + 4) + "\">" + xml_text(methods[k]) + "</text>\n";
    }
    return svg + "</svg>\n";
}

GrowthLines growth_lines(const std::vector<Measurement>& rows, const std::string& family) {
    GrowthLines g;
    double x_lo = 1e300, x_hi = -1e300, y_lo = 1e300, y_hi = -1e300;
    for (const Measurement& m : rows) {
        if (m.family != family || m.size <= 0) continue;
        auto line = std::find_if(g.lines.begin(), g.lines.end(), [&](const GrowthLine& l) { return l.method == m.method; });
        if (line == g.lines.end()) {
            const std::size_t cut = m.extra.find("; ");
            g.lines.push_back({m.method, {}, m.extra.substr(0, cut), cut == std::string::npos ? "" : m.extra.substr(cut + 2)});
            line = g.lines.end() - 1;
        }
        line->rows.push_back(&m);
        const double x = std::log10(m.size), y = std::log10(std::max(m.median_ms, 1e-6));
        x_lo = std::min(x_lo, x), x_hi = std::max(x_hi, x), y_lo = std::min(y_lo, y), y_hi = std::max(y_hi, y);
    }
    if (g.lines.empty()) return g;
    g.x_lo = std::floor(x_lo), g.x_hi = std::max(std::ceil(x_hi), g.x_lo + 1);
    g.y_lo = std::floor(y_lo), g.y_hi = std::max(std::ceil(y_hi), g.y_lo + 1);
    return g;
}

std::string growth_chart_svg(const std::vector<Measurement>& rows, const std::string& family) {
    // One line per method through its sizes, both axes log10; the legend gives each method's measured exponent.
    const GrowthLines g = growth_lines(rows, family);
    const double x_lo = g.x_lo, x_hi = g.x_hi, y_lo = g.y_lo, y_hi = g.y_hi;
    const int width = 900, height = 460, left = 70, right = 340, top = 40, bottom = 50;
    const auto x_of = [&](double x) { return left + (x - x_lo) / (x_hi - x_lo) * (width - left - right); };
    const auto y_of = [&](double y) { return top + (y_hi - y) / (y_hi - y_lo) * (height - top - bottom); };
    const bool against_P = family.find("(P)") != std::string::npos;
    std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(width) + "\" height=\"" + std::to_string(height) +
                      "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    svg += "<text x=\"" + std::to_string(left) + "\" y=\"22\" font-size=\"14\">" + xml_text(std::string(section_title(family))) + "</text>\n";
    for (double x = x_lo; x <= x_hi + 1e-9; x += 1)
        svg += "<line x1=\"" + number(x_of(x)) + "\" y1=\"" + std::to_string(top) + "\" x2=\"" + number(x_of(x)) + "\" y2=\"" +
               std::to_string(height - bottom) + "\" stroke=\"#ddd\"/><text x=\"" + number(x_of(x)) + "\" y=\"" + std::to_string(height - bottom + 16) +
               "\" text-anchor=\"middle\">1e" + std::to_string(int(x)) + "</text>\n";
    for (double y = y_lo; y <= y_hi + 1e-9; y += 1)
        svg += "<line x1=\"" + std::to_string(left) + "\" y1=\"" + number(y_of(y)) + "\" x2=\"" + std::to_string(width - right) + "\" y2=\"" +
               number(y_of(y)) + "\" stroke=\"#ddd\"/><text x=\"" + std::to_string(left - 6) + "\" y=\"" + number(y_of(y) + 4) +
               "\" text-anchor=\"end\">" + number(std::pow(10.0, y)) + "</text>\n";
    svg += "<text x=\"" + number((left + width - right) / 2.0) + "\" y=\"" + std::to_string(height - 12) + "\" text-anchor=\"middle\">" +
           (against_P ? "primitives P (log)" : "pixels p (log)") + "</text>\n";
    svg += "<text transform=\"translate(16," + number((top + height - bottom) / 2.0) +
           ") rotate(-90)\" text-anchor=\"middle\">median run time (ms, log)</text>\n";
    for (std::size_t k = 0; k < g.lines.size(); ++k) {
        const GrowthLine& line = g.lines[k];
        const std::string colour = chart_colour(k);
        std::string points;
        for (const Measurement* m : line.rows) {
            const double x = x_of(std::log10(m->size)), y = y_of(std::log10(std::max(m->median_ms, 1e-6)));
            points += number(x) + "," + number(y) + " ";
            svg += "<g><title>" + xml_text(m->method + ", " + m->setting + ": " + number(m->median_ms) + " ms") + "</title><circle cx=\"" +
                   number(x) + "\" cy=\"" + number(y) + "\" r=\"4\" fill=\"" + colour + "\"/></g>\n";
        }
        svg += "<polyline points=\"" + points + "\" fill=\"none\" stroke=\"" + colour + "\" stroke-width=\"2\"/>\n";
        const int y = top + 8 + int(k) * 52;
        svg += "<line x1=\"" + std::to_string(width - right + 12) + "\" y1=\"" + std::to_string(y) + "\" x2=\"" + std::to_string(width - right + 30) +
               "\" y2=\"" + std::to_string(y) + "\" stroke=\"" + colour + "\" stroke-width=\"3\"/><text x=\"" + std::to_string(width - right + 36) +
               "\" y=\"" + std::to_string(y + 4) + "\">" + xml_text(line.method) + "</text><text x=\"" + std::to_string(width - right + 36) +
               "\" y=\"" + std::to_string(y + 20) + "\" fill=\"#444\">" + xml_text(line.measured) + "</text><text x=\"" + std::to_string(width - right + 36) +
               "\" y=\"" + std::to_string(y + 36) + "\" fill=\"#444\">" + xml_text(line.claimed) + "</text>\n";
    }
    return svg + "</svg>\n";
}

std::string chart_svg(const std::vector<Measurement>& rows, const std::string& family) {
    const bool sweep = std::any_of(rows.begin(), rows.end(), [&](const Measurement& m) { return m.family == family && m.size > 0; });
    return sweep ? growth_chart_svg(rows, family) : error_chart_svg(rows, family);
}

}  // namespace hsr::analysis
