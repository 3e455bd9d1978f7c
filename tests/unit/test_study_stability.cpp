// The study's stability section: its stable intervals against fine scans on either side of
// every edge, and the overlap with condition (22) against the bulk cases' own intervals.
#include "helpers.hpp"
#include "stability/brillouin_zone.hpp"
#include "stability/stability_scan.hpp"
#include "study/sections/stability/stability_section.hpp"
#include "study/study.hpp"
#include "study/study_runner.hpp"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

using namespace sphkern;
using namespace sphkern::test;

TEST_CASE("a study's stable k intervals hold up under a finer scan, and the overlap is their intersection with (22)")
{
    auto document = nlohmann::json::parse(R"({
        "name": "stability-check", "kernels": ["cubic_bspline", "wendland_c2"], "lattices": ["triangular", "fcc"],
        "volume_coefficients": ["voronoi"], "k": {"min": 0.8, "max": 1.3, "samples": 101},
        "stability": {"k": {"steps": 25}, "dispersion_k": 1.1, "path_points": 40}})");
    const Study study = parse_study(document, "stability-check.json");
    const auto results = run_study(study, shipped_kernels());
    const auto* stability = section_results<StabilityResults>(results);
    REQUIRE(stability);
    REQUIRE(stability->cases.size() == 4);
    const double gamma = 5.0 / 3.0;
    for (const auto& c : stability->cases) {
        CAPTURE(c.lattice);
        CAPTURE(c.kernel_label);
        REQUIRE(!c.refused);
        const auto lattice = load_lattice(c.lattice);
        const Kernel kernel = shipped_kernel(c.kernel_label);
        const auto reciprocal = reciprocal_lattice(lattice);
        // A finer first grid (24 in 3D, 96 in 2D, three times the default) on each side of every edge inside the
        // window.
        auto stable_at = [&](double k) {
            return scan_brillouin_zone(Dispersion(kernel, lattice, k, gamma), reciprocal,
                                       3 * default_grid(lattice.dimension))
                .stable;
        };
        CHECK(c.over_k.samples.front().k == doctest::Approx(0.8));
        CHECK(c.over_k.samples.back().k == doctest::Approx(1.3));
        CHECK(!c.over_k.stable.empty());
        for (const auto& i : c.over_k.stable) {
            CAPTURE(i.from);
            CAPTURE(i.to);
            CHECK(stable_at(0.5 * (i.from + i.to)));
            if (i.from > 0.8 + 1e-9) {
                CHECK(stable_at(i.from + 2e-4));
                CHECK_FALSE(stable_at(i.from - 2e-4));
            }
            if (i.to < 1.3 - 1e-9) {
                CHECK(stable_at(i.to - 2e-4));
                CHECK_FALSE(stable_at(i.to + 2e-4));
            }
        }
        // The overlap: (22) from the bulk case, intersected with the intervals stable at the horizon.
        const StudyCase* bulk = nullptr;
        for (const auto& b : results.cases)
            if (b.lattice == c.lattice && b.kernel_label == c.kernel_label) bulk = &b;
        REQUIRE(bulk);
        REQUIRE(c.overlap.size() == 1);
        const auto& o = c.overlap.front();
        CHECK(o.accurate.size() == bulk->acceptance.intervals.size());
        for (double k = 0.8; k <= 1.3; k += 1e-3) {
            auto inside = [&](const auto& list) {
                return std::any_of(list.begin(), list.end(), [&](const auto& i) { return i.from < k && k < i.to; });
            };
            CHECK(inside(o.both) == (inside(bulk->acceptance.intervals) && inside(c.over_k.usable)));
        }
        // The dispersion curves: at the requested k, starting at Γ with omega^2 = 0.
        CHECK(c.path_k == 1.1);
        REQUIRE(!c.path.omega2.empty());
        CHECK(c.path.labels.front() == "Γ");
        for (double w : c.path.omega2.front()) CHECK(std::abs(w) < 1e-12);
        const Dispersion at(kernel, lattice, 1.1, gamma);
        CHECK(c.path.omega2.back() == at.omega2(high_symmetry_path(reciprocal).back().kappa));
    }
}
