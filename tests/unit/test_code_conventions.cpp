// sphkern's k in other codes' conventions: SWIFT's kernel gamma against the values SWIFT
// lists, and each conversion against its definition written out for the sc lattice.
#include "helpers.hpp"
#include "analysis/code_conventions.hpp"
#include "stability/recommended_k.hpp"
#include "support/error.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace sphkern;
using namespace sphkern::test;

TEST_CASE("SWIFT's kernel gamma H / (2 sigma) is the value SWIFT lists for its 3D kernels")
{
    // SWIFT's kernel_hydro.h, 3D: cubic, quartic and quintic spline, Wendland C2, C4, C6.
    const std::pair<const char*, double> listed[] = {{"cubic_bspline", 1.825742},
                                                     {"quartic_bspline", 2.018932},
                                                     {"morris_quintic", 2.195775},
                                                     {"wendland_c2", 1.936492},
                                                     {"wendland_c4", 2.207940},
                                                     {"wendland_c6", 2.449490}};
    for (const auto& [name, gamma] : listed) {
        CAPTURE(name);
        CHECK(swift_gamma(shipped_kernel(name), 3) == doctest::Approx(gamma).epsilon(1e-6));
    }
}

TEST_CASE("each convention follows from h = k d and H = R h, and SWIFT's eta 1.2348 with the cubic spline is GADGET's 48 neighbours")
{
    const Kernel cubic = shipped_kernel("cubic_bspline"); // R = 2
    const double k = 1.3, a_p = 1;                       // sc: dp = d
    const double H = 2 * k;
    CHECK(in_convention(code_convention("pysph", "--convention"), cubic, 3, a_p, k) == doctest::Approx(k));
    CHECK(in_convention(code_convention("dualsphysics", "--convention"), cubic, 3, a_p, k) ==
          doctest::Approx(H / (2 * std::sqrt(3.0))));
    CHECK(in_convention(code_convention("splishsplash", "--convention"), cubic, 3, a_p, k) == doctest::Approx(2 * H));
    CHECK(in_convention(code_convention("gadget", "--convention"), cubic, 3, a_p, k) ==
          doctest::Approx(4 * M_PI / 3 * H * H * H));
    CHECK(in_convention(code_convention("gadget", "--convention"), cubic, 2, a_p, k) == doctest::Approx(M_PI * H * H));
    // SWIFT's default eta = 1.2348 gives about 48 neighbours (its documentation): the same k both ways.
    const double swift_k = 1.2348 * 1.825742 / 2; // H = gamma eta dp = R k d
    CHECK(in_convention(code_convention("swift", "--convention"), cubic, 3, a_p, swift_k) == doctest::Approx(1.2348).epsilon(1e-6));
    CHECK(in_convention(code_convention("gadget", "--convention"), cubic, 3, a_p, swift_k) == doctest::Approx(48.0).epsilon(1e-3));
    // A volume coefficient scales the spacing: dp = a_p^(1/D) d.
    CHECK(in_convention(code_convention("pysph", "--convention"), cubic, 3, 0.5, k) == doctest::Approx(k / std::cbrt(0.5)));
    CHECK_THROWS_AS(code_convention("nosuch", "--convention"), Error);
}

TEST_CASE("the recommended k is the centre of the widest overlap, flagged when it touches the window")
{
    const auto lattice = load_lattice("fcc");
    const Kernel cubic = shipped_kernel("cubic_bspline");
    const HydrostaticErrors errors(cubic, lattice, 0, lattice.volume_per_site(), lattice.gravity, 1.3);
    const auto r = recommend_k({{0.80, 0.82}, {0.95, 1.05}, {1.10, 1.12}}, 0.75, 1.25, errors);
    REQUIRE(r.found);
    CHECK(r.k == doctest::Approx(1.0));
    CHECK(r.margin == doctest::Approx(0.05));
    CHECK(r.neighbours == errors.at(1.0).neighbours);
    CHECK_FALSE(r.at_window_edge);
    const auto edge = recommend_k({{1.0, 1.25}}, 0.75, 1.25, errors);
    CHECK(edge.at_window_edge);
    CHECK(recommended_text(edge).find(window_edge_note) != std::string::npos);
    CHECK_FALSE(recommend_k({}, 0.75, 1.25, errors).found);
}
