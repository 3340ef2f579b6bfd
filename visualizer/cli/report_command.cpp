// SPDX-License-Identifier: MIT
#include "cli/report_command.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "analysis/measurement.h"
#include "cli/commands.h"
#include "state/output_folder.h"
#include "analysis/report_files.h"
#include "state/lesson.h"

namespace hsr::viz {
namespace {

void write_file(const std::filesystem::path& path, const std::string& text) {
    std::ofstream f(path, std::ios::binary);
    f << text << std::flush;  // a full disk shows at the flush
    if (!f) throw std::runtime_error("cannot write " + path.string());
}

}  // namespace

int run_report(const ReportOptions& o) {
    if (!make_folder(o.out)) return 1;  // before minutes of measuring, not after
    const analysis::ReportOptions options{.quick = o.quick, .repeats = o.quick ? 3 : o.repeats, .scenes_dir = data_dir() + "/assets/scenes"};
    std::vector<analysis::Measurement> rows;
    for (auto* family : analysis::report_families()) {
        auto part = family(options);
        std::printf("%s: %zu rows\n", part.empty() ? "?" : part.front().family.c_str(), part.size());
        std::fflush(stdout);
        rows.insert(rows.end(), part.begin(), part.end());
    }
    const auto extremes = analysis::run_extreme_cases(data_dir() + "/assets/scenes/extreme");
    const std::filesystem::path dir(o.out);
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

}  // namespace hsr::viz
