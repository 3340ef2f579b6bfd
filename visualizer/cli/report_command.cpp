// SPDX-License-Identifier: MIT
#include "cli/report_command.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <new>
#include <stdexcept>

#include "analysis/measurement.h"
#include "cli/commands.h"
#include "state/output_folder.h"
#include "analysis/report_files.h"
#include "scene/input_file.h"
#include "state/lesson.h"

namespace hsr::viz {
namespace {

// "" when the scenes the report measures are there, else why not (HSRVIZ_DATA naming the wrong folder, say).
std::string missing_data() {
    std::error_code ec;
    for (const char* folder : {"/assets/scenes", "/assets/scenes/extreme"})
        if (!std::filesystem::is_directory(data_dir() + folder, ec))
            return "cannot read the shipped scenes in " + algo::printable(data_dir() + folder) +
                   ": no such folder (set HSRVIZ_DATA to the folder holding lessons/ and assets/)";
    return "";
}

int measure_and_write(const ReportOptions& o) {
    // before minutes of measuring, not after
    if (const std::string why = missing_data(); !why.empty()) throw std::runtime_error(why);
    if (!make_folder(o.out)) return 1;
    for (const char* file : {"report.md", "report.csv"})
        if (const std::string why = why_not_writable((std::filesystem::path(o.out) / file).string()); !why.empty())
            throw std::runtime_error(algo::printable(why) + "; nothing measured");
    const analysis::ReportOptions options{.quick = o.quick, .repeats = o.quick ? 3 : o.repeats, .scenes_dir = data_dir() + "/assets/scenes"};
    std::vector<analysis::Measurement> rows;
    for (const analysis::ReportSection& section : analysis::report_sections()) {
        auto part = section.measure(options);
        std::printf("%s: %zu rows\n", part.empty() ? "?" : part.front().family.c_str(), part.size());
        std::fflush(stdout);
        rows.insert(rows.end(), part.begin(), part.end());
    }
    const auto extremes = analysis::run_extreme_cases(data_dir() + "/assets/scenes/extreme");
    const std::filesystem::path dir(o.out);
    const auto write_file = [](const std::filesystem::path& path, const std::string& text) {
        if (const std::string why = write_whole_file(path.string(), text); !why.empty())
            throw std::runtime_error(algo::printable(why) + "; the measurements are not kept");
    };
    // the version that measured, in every file a person opens (the CSV stays plain rows for spreadsheets)
    write_file(dir / "report.md", "# hsrviz: error against run time\n\nWritten by hsrviz " HSR_VERSION " (`hsrviz report" +
                                      std::string(o.quick ? " --quick" : "") + "`); every number comes from this run.\n\n" +
                                      analysis::report_markdown(rows) +
                                      analysis::extreme_markdown(extremes));
    write_file(dir / "report.csv", analysis::report_csv(rows));
    for (const std::string& family : analysis::families_of(rows))
        write_file(dir / (family + ".svg"), "<!-- hsrviz " HSR_VERSION ": " + family + " -->\n" + analysis::chart_svg(rows, family));

    int violations = 0;
    for (const auto& m : rows)
        if (m.wrong_must_be_zero && m.wrong != 0) {
            std::printf("VIOLATION: %s, %s on %s: %llu\n", m.family.c_str(), m.method.c_str(), m.setting.c_str(), (unsigned long long)m.wrong);
            ++violations;
        }
    for (const auto& c : extremes) {
        if (!c.load_error.empty()) {
            std::printf("BROKEN PROMISE: %s does not load: %s\n", c.file.c_str(), c.load_error.c_str());
            ++violations;
        }
        for (const auto& x : c.outcomes)
            if (!x.passed) {
                std::printf("BROKEN PROMISE: %s:%d: %s: %s\n", c.file.c_str(), x.line, x.what.c_str(), x.detail.c_str());
                ++violations;
            }
    }
    std::printf("wrote %s/report.md, report.csv and %zu charts (%zu rows, %d violations)\n", o.out.c_str(),
                analysis::families_of(rows).size(), rows.size(), violations);
    return violations == 0 ? 0 : 1;
}

}  // namespace

int run_report(const ReportOptions& o) {
    try {
        return measure_and_write(o);
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "hsrviz report: out of memory\n");
    } catch (const std::exception& e) {  // a folder not written, a shipped scene that does not load

        std::fprintf(stderr, "hsrviz report: %s\n", algo::printable(e.what(), 2000).c_str());
    }
    return 1;
}

}  // namespace hsr::viz
