// SPDX-License-Identifier: MIT
#include "analysis/expect_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "analysis/exact_clip.h"
#include "analysis/exact_horizon.h"
#include "analysis/painters.h"
#include "bsp/bsp_scene.h"
#include "clipping/clip_scene.h"
#include "core/numeric.h"
#include "culling/backface.h"
#include "horizon/floating_horizon.h"
#include "portals/pvs.h"
#include "raycast/ray_cast.h"
#include "zbuffer/classic_scanline.h"
#include "zbuffer/scanline.h"
#include "zbuffer/zbuffer_fill.h"

namespace hsr::analysis {
namespace {

using namespace algo;

std::string number(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.3g", v);
    return b;
}

bool near(const Vec4& a, const Vec4& b) {
    for (int i = 0; i < 4; ++i)
        if (std::fabs(a[i] - b[i]) > 1e-12 * std::max(1.0, std::fabs(b[i]))) return false;
    return true;
}

// Polygons may start at any vertex: compare as cycles.
bool same_cycle(const std::vector<Vec4>& got, const std::vector<Vec4>& want) {
    if (got.size() != want.size()) return false;
    for (std::size_t shift = 0; shift < got.size(); ++shift) {
        bool all = true;
        for (std::size_t i = 0; i < got.size() && all; ++i) all = near(got[(i + shift) % got.size()], want[i]);
        if (all) return true;
    }
    return got.empty();
}

// The loader has checked the name.
SplitterRule rule_named(const std::string& s) { return parse_splitter_rule(s).value_or(SplitterRule::first); }

DepthFormat format_named(const std::string& s) {
    using F = DepthFormat;
    for (F f : {F::int16, F::int24, F::int32, F::float32, F::float32_reversed, F::linear24})
        if (s == format_id(f)) return f;
    return F::int24;
}

const char* clip_name(ClipAlgorithm a) {
    return a == ClipAlgorithm::cohen_sutherland ? "cohen_sutherland" : a == ClipAlgorithm::liang_barsky ? "liang_barsky" : "sutherland_hodgman";
}

// The largest relative error of the machine's visible part against the exact answer for the same input.
double exact_error(const ClipJob& job, SceneId id, const std::vector<Vec4>& got) {
    double scale = 0;
    const auto scale_of = [&](const std::vector<Vec4>& v) {
        for (const Vec4& p : v)
            for (int i = 0; i < 4; ++i) scale = std::max(scale, std::fabs(p[i]));
    };
    for (const ClipSegment& s : job.segments)
        if (s.id == id) {
            scale_of({s.p1, s.p2});
            const ExactSegment x = exact_clip_segment(s.p1, s.p2, job.space);
            if (!x.visible) return got.empty() ? 0 : 1e300;
            if (got.size() != 2) return 1e300;
            return std::max(relative_error(got[0], x.a, scale), relative_error(got[1], x.b, scale));
        }
    for (const ClipPolygon& p : job.polygons)
        if (p.id == id) {
            scale_of(p.vertices);
            const std::vector<ExactPoint> x = exact_clip_polygon(p.vertices, job.space);
            if (x.empty() != got.empty()) return 1e300;
            return vertex_set_error(got, x, scale);
        }
    return 0;  // a point: no intersection, nothing to round
}

void check_clip(const Scene& scene, std::vector<ExpectOutcome>& out) {
    if (scene.expect.clip.empty()) return;
    const ClipJob job = clip_job(scene);
    std::vector<int> answered(scene.expect.clip.size(), 0);
    for (const ClipAlgorithm algorithm : {ClipAlgorithm::cohen_sutherland, ClipAlgorithm::liang_barsky, ClipAlgorithm::sutherland_hodgman}) {
        const auto answers = clip_scene(job, algorithm).run_to_end();
        for (std::size_t k = 0; k < scene.expect.clip.size(); ++k) {
            const ExpectClip& x = scene.expect.clip[k];
            const auto it = std::find_if(answers.begin(), answers.end(), [&](auto& a) { return a.id == x.id; });
            if (it == answers.end()) continue;  // not a primitive this algorithm clips
            ++answered[k];
            ExpectOutcome o{"expect.clip id " + std::to_string(x.id) + " by " + clip_name(algorithm), x.line, true, 0, ""};
            const std::string got(to_string(it->outcome));
            if (got != x.outcome) o.passed = false, o.detail = "outcome " + got + ", expected " + x.outcome;
            if (x.vertices && !same_cycle(it->vertices, *x.vertices)) o.passed = false, o.detail += " the vertices differ from those listed";
            o.error = exact_error(job, x.id, it->outcome == ClipOutcome::rejected ? std::vector<Vec4>{} : it->vertices);
            if (x.max_error && !(o.error <= *x.max_error))
                o.passed = false, o.detail += " error " + number(o.error) + " above the promised " + number(*x.max_error);
            if (o.passed) o.detail = got + ", error " + number(o.error) + " against the exact answer";
            out.push_back(std::move(o));
        }
    }
    for (std::size_t k = 0; k < answered.size(); ++k)
        if (!answered[k])
            out.push_back({"expect.clip id " + std::to_string(scene.expect.clip[k].id), scene.expect.clip[k].line, false, 0,
                           "no clipping machine clips this primitive"});
}

void check_cull(const Scene& scene, std::vector<ExpectOutcome>& out) {
    for (const ExpectCull& x : scene.expect.cull)
        for (const auto& [test, name] : {std::pair{BackfaceTest::view_vector, "view_vector"}, std::pair{BackfaceTest::plane_equation, "plane_equation"},
                                         std::pair{BackfaceTest::screen_winding, "screen_winding"}}) {
            if (x.test && *x.test != name) continue;
            const auto kept = cull_back_faces(faces_of(scene), scene.camera, test).run_to_end();
            std::string ids;
            for (auto id : kept) ids += (ids.empty() ? "" : ", ") + std::to_string(id);
            out.push_back({std::string("expect.cull by ") + name, x.line, kept == x.kept, 0, "kept [" + ids + "]"});
        }
}

void check_bsp(const Scene& scene, std::vector<ExpectOutcome>& out) {
    for (const ExpectBsp& x : scene.expect.bsp) {
        BspJob job = bsp_job(scene, rule_named(x.splitter));  // as a lesson builds it: polygons, or a 2D scene's segments
        const BspTree tree = build_bsp(std::move(job.polygons), job.options).run_to_end();
        ExpectOutcome o{"expect.bsp " + x.splitter, x.line, true, 0, std::to_string(tree.splits) + " splits"};
        if (x.splits && int(tree.splits) != *x.splits) o.passed = false, o.detail += ", expected " + std::to_string(*x.splits);
        if (x.order) {
            std::vector<SceneId> painted;
            for (BspPolygonId p : traverse_bsp(&tree, *x.eye).run_to_end()) painted.push_back(tree.polygons[std::size_t(p)].source);
            if (painted != *x.order) o.passed = false, o.detail += ", a different painting order";
        }
        out.push_back(std::move(o));
    }
}

void check_pvs(const Scene& scene, std::vector<ExpectOutcome>& out) {
    if (scene.expect.pvs.empty()) return;
    const CellModel model = cell_model(scene);
    const Pvs pvs = build_pvs(&model).run_to_end();
    for (const ExpectPvs& x : scene.expect.pvs) {
        const auto named = [&](const std::string& name) {
            return std::uint32_t(std::find_if(model.cells.begin(), model.cells.end(), [&](const Cell& c) { return c.name == name; }) -
                                 model.cells.begin());
        };
        std::vector<std::string> got, want = x.visible;
        for (std::uint32_t c : pvs.row(named(x.cell))) got.push_back(model.cells[c].name);
        std::sort(want.begin(), want.end());
        std::sort(got.begin(), got.end());
        std::string names;
        for (const auto& n : got) names += (names.empty() ? "" : ", ") + n;
        out.push_back({"expect.pvs " + x.cell, x.line, got == want, 0, "sees " + names});
    }
}

std::vector<SceneId> image_of(const Scene& scene, const std::string& algorithm, const ExpectImage& x) {
    const Viewport vp{x.width, x.height};
    if (algorithm == "zbuffer")
        return zbuffer_fill(project_polygons(scene, vp), zbuffer_options(scene, vp, format_named(x.format), EventDetail::polygon)).run_to_end().image.ids;
    if (algorithm == "scanline" || algorithm == "scanline-classic") {
        ScanLineOptions o = scan_line_options(scene, vp, format_named(x.format));
        o.tell_crossings = false;
        if (algorithm == "scanline-classic") return classic_scan_line(project_polygons(scene, vp), {.line = o}).run_to_end().image.ids;
        return scan_line(project_polygons(scene, vp), o).run_to_end().image.ids;
    }
    if (algorithm == "bsp") return paint_bsp(scene, rule_named(x.splitter), vp).image.ids;
    if (algorithm == "depth-sort") return paint_depth_sort(scene, vp).image.ids;
    return ray_cast(scene, {.viewport = vp, .acceleration = Acceleration::grid, .detail = RayDetail::ray}).run_to_end().image.ids;
}

void check_images(const Scene& scene, std::vector<ExpectOutcome>& out) {
    for (const ExpectImage& x : scene.expect.image) {
        std::string what = "expect.image " + x.algorithm + (x.algorithm == "zbuffer" || x.algorithm.starts_with("scanline") ? " " + x.format : "") +
                           (x.algorithm == "bsp" ? " " + x.splitter : "");
        try {
            const auto got = image_of(scene, x.algorithm, x);
            const auto ref = image_of(scene, "raycast", x);
            std::size_t differ = 0;
            for (std::size_t k = 0; k < got.size(); ++k) differ += got[k] != ref[k];
            const double share = double(differ) / double(got.size());
            ExpectOutcome o{what, x.line, true, share, number(100 * share) + "% of pixels differ from the ray cast"};
            if (x.max_differing && share > *x.max_differing) o.passed = false, o.detail += ", above the promised " + number(100 * *x.max_differing) + "%";
            if (x.min_differing && share < *x.min_differing) o.passed = false, o.detail += ", below the " + number(100 * *x.min_differing) + "% the case shows";
            for (SceneId id : x.visible)
                if (std::find(got.begin(), got.end(), id) == got.end()) o.passed = false, o.detail += ", id " + std::to_string(id) + " never seen";
            out.push_back(std::move(o));
        } catch (const std::exception& e) {
            out.push_back({what, x.line, false, 0, std::string("refused: ") + e.what()});
        }
    }
}

void check_rejects(const Scene& scene, std::vector<ExpectOutcome>& out) {
    for (const ExpectRejects& x : scene.expect.rejects) {
        ExpectOutcome o{"expect.rejects " + x.algorithm, x.line, false, 0, "accepted the scene"};
        try {
            image_of(scene, x.algorithm, ExpectImage{.algorithm = x.algorithm, .width = 16, .height = 12, .line = x.line});
        } catch (const std::exception& e) {
            o.detail = std::string("refused: ") + e.what();
            o.passed = std::string(e.what()).find(x.message) != std::string::npos;
            if (!o.passed) o.detail += " (expected a message with \"" + x.message + "\")";
        }
        out.push_back(std::move(o));
    }
}

void check_horizon(const Scene& scene, std::vector<ExpectOutcome>& out) {
    for (const ExpectHorizon& x : scene.expect.horizon) {
        const std::string what = "expect.horizon " + std::to_string(x.columns) + " columns";
        try {
            const HorizonImage image = floating_horizon(scene.terrain, {.columns = x.columns}).run_to_end();
            const HorizonReference exact = exact_horizon(scene.terrain, x.columns);
            double largest = scene.terrain.rows * scene.terrain.dz;  // what a screen y is made of
            for (const double h : scene.terrain.heights) largest = std::max(largest, std::abs(h));
            std::uint64_t visible = 0, differing = 0, near_ties = 0;
            for (std::size_t k = 0; k < image.sight.size(); ++k) {
                const bool shown = image.sight[k] != Sight::hidden;
                visible += shown;
                if (shown != exact.visible[k]) ++(exact.margin[k] <= 1e-12 * largest ? near_ties : differing);
            }
            const bool count_right = !x.visible || *x.visible == visible;
            out.push_back({what, x.line, differing == 0 && count_right, double(near_ties) / double(image.sight.size()),
                           std::to_string(visible) + " of " + std::to_string(image.sight.size()) + " points seen" +
                               (x.visible ? " (expected " + std::to_string(*x.visible) + ")" : "") + "; " + std::to_string(differing) +
                               " differ from the exact ray walk, " + std::to_string(near_ties) + " within a relative 1e-12 of a tie"});
        } catch (const std::exception& e) {
            out.push_back({what, x.line, false, 0, std::string("refused: ") + e.what()});
        }
    }
}

}  // namespace

std::vector<ExpectOutcome> check_expectations(const Scene& scene) {
    std::vector<ExpectOutcome> out;
    check_clip(scene, out);
    check_cull(scene, out);
    check_bsp(scene, out);
    check_pvs(scene, out);
    check_images(scene, out);
    check_rejects(scene, out);
    check_horizon(scene, out);
    return out;
}

}  // namespace hsr::analysis
