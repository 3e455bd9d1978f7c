// Shell sums against an independent brute-force sum, eq. (21) in closed form, roots
// against brute force, and the paper's Table 1 in the paper-compatible mode.
#include "analysis/acceptance.hpp"
#include "analysis/roots.hpp"
#include "helpers.hpp"
#include "support/io/install_paths.hpp"
#include "support/io/json_input.hpp"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <map>
#include <set>

using namespace sphkern;
using sphkern::test::brute_force_errors;
using sphkern::test::shipped_kernel;

TEST_CASE("shell sums equal a brute-force sum over lattice points, 2D and 3D")
{
    for (const char* lattice_name : {"triangular", "square", "fcc", "bcc", "sc", "hcp", "hex_prism"})
        for (const char* kernel_name : {"cubic_bspline", "morris_quintic", "wendland_c4", "super_gaussian"}) {
            auto lattice = load_lattice(lattice_name);
            Kernel kernel = shipped_kernel(kernel_name);
            double a_p = lattice.volume_coefficient("voronoi");
            HydrostaticErrors errors(kernel, lattice, 0, a_p, lattice.gravity, 1.25);
            for (double k : {0.8, 0.97, 1.1, 1.25}) {
                CAPTURE(lattice_name);
                CAPTURE(kernel_name);
                CAPTURE(k);
                auto expected = brute_force_errors(kernel, lattice, k, a_p, lattice.gravity);
                auto got = errors.at(k);
                CHECK(got.eps_rho == doctest::Approx(expected.eps_rho).epsilon(1e-12));
                CHECK(got.eps_gradp == doctest::Approx(expected.eps_gradp).epsilon(1e-12));
            }
        }
}

TEST_CASE("eq. (21) for R = 2 on the triangular lattice")
{
    auto lattice = load_lattice("triangular");
    Kernel kernel = shipped_kernel("cubic_bspline");
    double a_p = std::sqrt(3.0) / 2;
    HydrostaticErrors errors(kernel, lattice, 0, a_p, lattice.gravity, 1.2);
    for (double k : {1.0, 1.1, 1.2}) {
        auto dW = [&](double r) { return kernel.dw(r / k, 2, k) / std::pow(k, 3); };
        double closed = -a_p * (3 * dW(1) + 3 * std::sqrt(3.0) * dW(std::sqrt(3.0)) + 6 * dW(2)) - 1;
        CHECK(errors.at(k).eps_gradp == doctest::Approx(closed).epsilon(1e-13));
    }
}

TEST_CASE("roots agree with a brute-force evaluation to 1e-9 in 2D and 3D")
{
    for (const char* lattice_name : {"triangular", "fcc", "bcc"})
        for (const char* kernel_name : {"cubic_bspline", "morris_quintic", "wendland_c2", "liu_quartic"}) {
            auto lattice = load_lattice(lattice_name);
            Kernel kernel = shipped_kernel(kernel_name);
            for (const char* ap : {"voronoi", "ball"}) {
                double a_p = lattice.volume_coefficient(ap);
                HydrostaticErrors errors(kernel, lattice, 0, a_p, lattice.gravity, 1.25);
                for (const auto& root : find_roots(errors, 0.75, 1.25).roots) {
                    CAPTURE(lattice_name);
                    CAPTURE(kernel_name);
                    CAPTURE(root.k);
                    auto value = [&](double k) {
                        auto v = brute_force_errors(kernel, lattice, k, a_p, lattice.gravity);
                        return root.function == ErrorFunction::rho ? v.eps_rho : v.eps_gradp;
                    };
                    double below = value(root.k - 1e-9), above = value(root.k + 1e-9);
                    CHECK(std::signbit(below) != std::signbit(above));
                }
            }
        }
}

TEST_CASE("a sign change across a breakpoint is a jump, not a root, and the composite pole is harmless")
{
    // The super-Gaussian truncated at R = 3 (W'(3) != 0): eps_gradP changes sign where the
    // sqrt(7) shell enters the support, at k = sqrt(7)/3.
    auto lattice = load_lattice("triangular");
    HydrostaticErrors gaussian(shipped_kernel("super_gaussian"), lattice, 0, std::sqrt(3.0) / 2, lattice.gravity, 1.25);
    auto scan = find_roots(gaussian, 0.75, 1.25);
    const double k_b = std::sqrt(7.0) / 3;
    bool jump = false;
    for (const auto& j : scan.jumps)
        if (j.function == ErrorFunction::gradp && std::abs(j.k - k_b) < 1e-14) {
            jump = true;
            CHECK(j.left == doctest::Approx(gaussian.at_piece(k_b, 3).eps_gradp));
            CHECK(std::signbit(j.left) != std::signbit(j.right));
        }
    CHECK(jump);
    for (const auto& r : scan.roots) {
        CHECK(std::abs(r.k - k_b) > 1e-6);
        CHECK(std::abs(value_of(r.values, r.function)) < 1e-8);
    }
    // Eq. (13b) is singular at k = 63/74, where no lattice point is inside the R = 1 support:
    // the errors stay finite and the roots are real roots.
    Kernel composite = shipped_kernel("composite");
    HydrostaticErrors errors(composite, lattice, 0, std::sqrt(3.0) / 2, lattice.gravity, 1.25);
    CHECK(std::isfinite(errors.at(63.0 / 74).eps_gradp));
    for (const auto& r : find_roots(errors, 0.75, 1.25).roots) CHECK(std::abs(value_of(r.values, r.function)) < 1e-8);
}

TEST_CASE("Table 1 of the paper in the paper-compatible mode, to 1e-4, without tuning")
{
    auto document = read_json_file(data_folder("reference") / "potapov2021-table1.json");
    auto lattice = load_lattice("triangular");
    const double a_p = lattice.volume_coefficient("voronoi");
    const std::map<int, std::vector<double>> shells = {{1, {1}},
                                                       {2, {1, std::sqrt(3.0), 2}},
                                                       {3, {1, std::sqrt(3.0), 2, std::sqrt(7.0), 3}}};
    const std::set<std::string> continued = {"super_gaussian", "liu_quartic", "johnson_quadratic", "muller_poly6"};
    int checked = 0;
    for (const auto& row : document["rows"]) {
        std::string name = row["kernel"];
        Kernel kernel = shipped_kernel(name);
        EvaluationMode mode;
        mode.shell_radii = shells.at(static_cast<int>(kernel.support()));
        mode.continue_past_support = continued.count(name) > 0;
        HydrostaticErrors errors(kernel, lattice, 0, a_p, lattice.gravity, 1.25, mode);
        auto scan = find_roots(errors, 0.75, 1.25);
        CAPTURE(row.dump());
        if (row.value("no_root", false)) {
            CHECK(scan.roots.empty());
            continue;
        }
        if (row.contains("erratum")) continue; // the composite gradient row: see share/docs/method.md, errata
        const auto function =
            row["eps_gradp"].is_number() && row["eps_gradp"] == 0 ? ErrorFunction::gradp : ErrorFunction::rho;
        const Root* best = nullptr;
        for (const auto& r : scan.roots)
            if (r.function == function &&
                (!best || std::abs(r.k - row["k"].get<double>()) < std::abs(best->k - row["k"].get<double>())))
                best = &r;
        REQUIRE(best);
        CHECK(std::abs(best->k - row["k"].get<double>()) <= 1e-4);
        CHECK(std::abs(best->values.eps_rho - row["eps_rho"].get<double>()) <= 1e-4);
        if (row["eps_gradp"].is_number() && !row.contains("erratum_eps_gradp"))
            CHECK(std::abs(best->values.eps_gradp - row["eps_gradp"].get<double>()) <= 1e-4);
        ++checked;
    }
    CHECK(checked == 19);
}

TEST_CASE("condition (22) intervals hold inside and fail outside")
{
    auto lattice = load_lattice("triangular");
    Kernel kernel = shipped_kernel("morris_quintic");
    HydrostaticErrors errors(kernel, lattice, 0, lattice.volume_coefficient("voronoi"), lattice.gravity, 1.25);
    auto acceptance = evaluate_acceptance(errors, 0.75, 1.25, 0.001);
    REQUIRE(acceptance.passes());
    for (const auto& i : acceptance.intervals) {
        auto mid = errors.at(0.5 * (i.from + i.to));
        CHECK(std::abs(mid.eps_rho) <= 0.001);
        CHECK(std::abs(mid.eps_gradp) <= 0.001);
        if (i.from > 0.75 + 1e-9) {
            auto outside = errors.at(i.from - 1e-6);
            CHECK(std::max(std::abs(outside.eps_rho), std::abs(outside.eps_gradp)) > 0.001);
        }
    }
}
