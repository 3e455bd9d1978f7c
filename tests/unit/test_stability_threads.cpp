// The scans shared out over threads give the same answers, bit for bit, on 1, 2 and 3 threads:
// the scan over k (its curve, the k looked at between and both kinds of interval), roots
// --stability's document, and design's scan along the parameter.
#include "analysis/acceptance.hpp"
#include "analysis/design.hpp"
#include "analysis/hydrostatic_errors.hpp"
#include "helpers.hpp"
#include "stability/roots_stability.hpp"
#include "stability/stability_over_k.hpp"

#include <doctest/doctest.h>

#include <nlohmann/json.hpp>

#include <vector>

using namespace sphkern;
using namespace sphkern::test;

namespace {

void same_samples(const std::vector<StabilitySample>& a, const std::vector<StabilitySample>& b)
{
    REQUIRE(a.size() == b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        CAPTURE(a[i].k);
        CHECK(a[i].k == b[i].k);
        CHECK(a[i].branch_minima == b[i].branch_minima);
        CHECK(a[i].stable == b[i].stable);
        CHECK(a[i].verdict == b[i].verdict);
        CHECK(a[i].at == b[i].at);
        CHECK(a[i].growth_time == b[i].growth_time);
        CHECK(a[i].floor == b[i].floor);
        CHECK(a[i].long_wave == b[i].long_wave);
    }
}

void same_intervals(const std::vector<KInterval>& a, const std::vector<KInterval>& b)
{
    REQUIRE(a.size() == b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        CHECK(a[i].from == b[i].from);
        CHECK(a[i].to == b[i].to);
    }
}

} // namespace

TEST_CASE("the scan over k is the same on 1, 2 and 3 threads: the quartic spline on fcc")
{
    const Kernel kernel = shipped_kernel("quartic_bspline");
    const auto lattice = load_lattice("fcc");
    std::vector<StabilityOverK> runs;
    for (int threads : {1, 2, 3})
        runs.push_back(stability_over_k(kernel, lattice, 0.8, 1.3, 10, 5.0 / 3.0, 0, threads));
    REQUIRE_FALSE(runs[0].between.empty());
    for (std::size_t i = 1; i < runs.size(); ++i) {
        CAPTURE(i + 1);
        same_samples(runs[0].samples, runs[i].samples);
        same_samples(runs[0].between, runs[i].between);
        same_intervals(runs[0].stable, runs[i].stable);
        same_intervals(runs[0].usable, runs[i].usable);
    }
}

TEST_CASE("roots --stability is the same document on 1, 2 and 3 threads: the cubic B-spline on hcp (two sites)")
{
    const Kernel kernel = shipped_kernel("cubic_bspline");
    const auto lattice = load_lattice("hcp");
    const double k_min = 0.9, k_max = 1.05;
    const HydrostaticErrors errors(kernel, lattice, 0, lattice.volume_coefficient("voronoi"), lattice.gravity, k_max);
    const auto accurate = evaluate_acceptance(errors, k_min, k_max, 0.05).intervals;
    std::vector<std::string> documents;
    for (int threads : {1, 2, 3})
        documents.push_back(roots_stability(kernel, lattice, k_min, k_max, {5.0 / 3.0, 100, 10, HModel::fixed, threads},
                                            accurate, errors)
                                .json.dump());
    CHECK(documents[0].find("stable_intervals") != std::string::npos);
    CHECK(documents[1] == documents[0]);
    CHECK(documents[2] == documents[0]);
}

TEST_CASE("design finds the same solutions on 1, 2 and 3 threads: the wendland_c2_shape family on fcc")
{
    const auto lattice = load_lattice("fcc");
    const Kernel family = shipped_kernel("wendland_c2_shape");
    std::vector<DesignResult> results;
    for (int threads : {1, 2, 3}) {
        DesignProblem problem;
        problem.lattice = &lattice;
        problem.a_p = lattice.volume_coefficient("voronoi");
        problem.gravity = lattice.gravity;
        problem.parameter = "beta";
        problem.parameter_min = -1;
        problem.parameter_max = 10;
        problem.threads = threads;
        results.push_back(design_kernel(family, problem));
    }
    REQUIRE_FALSE(results[0].solutions.empty());
    for (std::size_t i = 1; i < results.size(); ++i) {
        REQUIRE(results[i].solutions.size() == results[0].solutions.size());
        for (std::size_t s = 0; s < results[0].solutions.size(); ++s) {
            CHECK(results[i].solutions[s].k == results[0].solutions[s].k);
            CHECK(results[i].solutions[s].parameter == results[0].solutions[s].parameter);
            CHECK(results[i].solutions[s].jacobian_condition == results[0].solutions[s].jacobian_condition);
        }
    }
}
