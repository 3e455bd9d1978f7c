// The zone scanner and the scan over k against an independent fine scan: a dense grid over
// the reciprocal cell (every point, no symmetry) with a pattern search from its valleys,
// and long waves from omega^2 / kappa^2 at a small kappa in many directions. The three
// intervals once reported stable although unstable, interval edges, the agreement of one k
// with the scan over k, the horizon, the kinds of mode and the long-wave figure of hcp.
#include "helpers.hpp"
#include "stability/brillouin_zone.hpp"
#include "stability/dispersion.hpp"
#include "stability/mode_kind.hpp"
#include "stability/stability_over_k.hpp"
#include "stability/stability_scan.hpp"
#include "stability/zone_grid.hpp"
#include "stability/zone_minimum.hpp"
#include "stability/zone_symmetry.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

using namespace sphkern;
using namespace sphkern::test;

namespace {

constexpr double gamma_53 = 5.0 / 3.0;

double lowest(const Dispersion& d, const Eigen::Matrix3d& b, const Eigen::Vector3d& f)
{
    return d.omega2(b * f).front();
}

// From fractions f: steps of s along each axis while one improves, halving s otherwise.
double pattern_search(const Dispersion& d, const Eigen::Matrix3d& b, Eigen::Vector3d f, double s)
{
    double value = lowest(d, b, f);
    while (s > 1e-8) {
        bool moved = false;
        for (int axis = 0; axis < d.dimension(); ++axis)
            for (double sign : {-1.0, 1.0}) {
                Eigen::Vector3d g = f;
                g[axis] += sign * s;
                const double v = lowest(d, b, g);
                if (v < value) value = v, f = g, moved = true;
            }
        if (!moved) s /= 2;
    }
    return value;
}

// The lowest omega^2 over the zone: every point of an n^D grid, then a pattern search from
// the 16 lowest grid points that are no higher than their axis neighbours.
double independent_minimum(const Dispersion& d, const Eigen::Matrix3d& b, int n)
{
    const int D = d.dimension();
    const int total = D == 3 ? n * n * n : n * n;
    std::vector<std::pair<double, Eigen::Vector3d>> points;
    for (int i = 0; i < total; ++i) {
        const Eigen::Vector3d f(double(i % n) / n, double(i / n % n) / n, D == 3 ? double(i / (n * n)) / n : 0);
        points.emplace_back(lowest(d, b, f), f);
    }
    std::vector<std::pair<double, Eigen::Vector3d>> valleys;
    for (const auto& [v, f] : points) {
        bool floor = true;
        for (int axis = 0; axis < D && floor; ++axis)
            for (double sign : {-1.0, 1.0}) {
                Eigen::Vector3d g = f;
                g[axis] += sign / n;
                floor = floor && lowest(d, b, g) >= v;
            }
        if (floor) valleys.emplace_back(v, f);
    }
    std::sort(valleys.begin(), valleys.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    double best = points.empty() ? 0 : std::min_element(points.begin(), points.end(), [](const auto& x, const auto& y) {
                                           return x.first < y.first;
                                       })->first;
    for (std::size_t i = 0; i < std::min<std::size_t>(16, valleys.size()); ++i)
        best = std::min(best, pattern_search(d, b, valleys[i].second, 0.5 / n));
    return best;
}

// omega^2 / kappa^2 of the lowest branch at kappa = 1e-3 over a Fibonacci sphere (circle in 2D).
double independent_long_wave(const Dispersion& d)
{
    double best = INFINITY;
    const int count = 600;
    for (int i = 0; i < count; ++i) {
        Eigen::Vector3d n;
        if (d.dimension() == 3) {
            const double z = 1 - (2.0 * i + 1) / count, phi = i * M_PI * (3 - std::sqrt(5.0));
            n = {std::sqrt(1 - z * z) * std::cos(phi), std::sqrt(1 - z * z) * std::sin(phi), z};
        } else {
            n = {std::cos(M_PI * i / count), std::sin(M_PI * i / count), 0};
        }
        best = std::min(best, d.omega2(1e-3 * n).front() / 1e-6);
    }
    return best;
}

bool independently_stable(const Kernel& kernel, const Lattice& lattice, double k, int n)
{
    const Dispersion d(kernel, lattice, k, gamma_53);
    const Eigen::Matrix3d b = reciprocal_lattice(lattice).vectors;
    return independent_minimum(d, b, n) >= -unstable_threshold && independent_long_wave(d) >= -unstable_threshold;
}

bool inside(const std::vector<KInterval>& list, double k)
{
    return std::any_of(list.begin(), list.end(), [&](const KInterval& i) { return i.from <= k && k <= i.to; });
}

} // namespace

TEST_CASE("the k once reported stable in three unstable intervals are unstable, as a fine independent scan says")
{
    struct Case {
        const char* kernel;
        const char* lattice;
        std::vector<double> ks;
    };
    // morris_quintic on fcc: unstable on [0.8897, 0.8924]; Wendland C2 on fcc [2.5142, 2.5213]
    // and on hcp [1.8965, 1.9125], unstable throughout.
    const std::vector<Case> cases{{"morris_quintic", "fcc", {0.8900, 0.8910, 0.8920}},
                                  {"wendland_c2", "fcc", {2.5150, 2.5180, 2.5210}},
                                  {"wendland_c2", "hcp", {1.8970, 1.9050, 1.9120}}};
    for (const auto& c : cases) {
        const Kernel kernel = shipped_kernel(c.kernel);
        const auto lattice = load_lattice(c.lattice);
        const auto reciprocal = reciprocal_lattice(lattice);
        for (double k : c.ks) {
            CAPTURE(c.kernel);
            CAPTURE(c.lattice);
            CAPTURE(k);
            const Dispersion d(kernel, lattice, k, gamma_53);
            const double independent = independent_minimum(d, reciprocal.vectors, lattice.sites() > 1 ? 16 : 24);
            CHECK(independent < -unstable_threshold);
            const auto scan = scan_brillouin_zone(d, reciprocal, 0, 1, false);
            CHECK_FALSE(scan.stable);
            // The depth too: within the zone tolerance (1e-4 of the minimum) of the independent
            // minimum, now that the refinement also searches along the valley (Wendland C2 on
            // fcc near k = 2.52 was 2.1% shallower with coordinate sweeps alone).
            CHECK_MESSAGE(scan.lowest().omega2 <= independent * (1 - zone_tolerance_relative),
                          "scan " << scan.lowest().omega2 << " independent " << independent << " ratio "
                                  << scan.lowest().omega2 / independent);
        }
        // The scan over k: none of these k is in a stable interval.
        const auto over_k =
            stability_over_k(kernel, lattice, c.ks.front() - 0.01, c.ks.back() + 0.01, 4, gamma_53, 0, 1);
        for (double k : c.ks) CHECK_FALSE(inside(over_k.stable, k));
    }
}

namespace {

// The stable intervals of [from, to] over k: each edge inside the window holds against a fine
// independent scan on either side, and every k the scan looked at gets the verdict of that k's
// scan alone. Returns the edges checked.
int edges_against_independent_scan(const char* kernel_name, const char* lattice_name, double from, double to, int steps)
{
    CAPTURE(kernel_name);
    CAPTURE(lattice_name);
    const double within = 2e-5; // the independent scan's verdict on either side of each edge
    int edges = 0;
    const Kernel kernel = shipped_kernel(kernel_name);
    const auto lattice = load_lattice(lattice_name);
    const auto reciprocal = reciprocal_lattice(lattice);
    const int n = lattice.dimension == 2 ? 96 : lattice.sites() > 1 ? 16 : 24;
    const auto over_k = stability_over_k(kernel, lattice, from, to, steps, gamma_53, 0, 1);
    for (const auto& i : over_k.stable) {
        CAPTURE(i.from);
        CAPTURE(i.to);
        if (i.from > from + 1e-9) {
            CHECK(independently_stable(kernel, lattice, i.from + within, n));
            CHECK_FALSE(independently_stable(kernel, lattice, i.from - within, n));
            ++edges;
        }
        if (i.to < to - 1e-9) {
            CHECK(independently_stable(kernel, lattice, i.to - within, n));
            CHECK_FALSE(independently_stable(kernel, lattice, i.to + within, n));
            ++edges;
        }
    }
    // Every sample and every k looked at between them: the scan of that k alone says the same.
    auto agree = [&](const StabilitySample& s) {
        CAPTURE(s.k);
        const auto alone = scan_brillouin_zone(Dispersion(kernel, lattice, s.k, gamma_53), reciprocal, 0, 1, true);
        CHECK(alone.stable == s.stable);
        CHECK(alone.verdict(default_horizon) == s.verdict);
        CHECK(alone.lowest().omega2 == s.branch_minima.front());
    };
    for (const auto& s : over_k.samples) agree(s);
    for (const auto& s : over_k.between) agree(s);
    return edges;
}

} // namespace

// One case per window, each well under the suite's 20 s a test.
TEST_CASE("stable interval edges agree with a fine independent scan, and one k agrees with the scan over k: "
          "morris_quintic on fcc")
{
    CHECK(edges_against_independent_scan("morris_quintic", "fcc", 0.86, 0.92, 6) == 2);
}

TEST_CASE("stable interval edges agree with a fine independent scan, and one k agrees with the scan over k: "
          "cubic_bspline on fcc")
{
    CHECK(edges_against_independent_scan("cubic_bspline", "fcc", 0.85, 1.10, 5) == 2);
}

TEST_CASE("stable interval edges agree with a fine independent scan, and one k agrees with the scan over k: "
          "wendland_c2 on hcp")
{
    // No stable interval in this window: every k looked at still agrees with its scan alone.
    CHECK(edges_against_independent_scan("wendland_c2", "hcp", 1.88, 1.93, 5) == 0);
}

TEST_CASE("stable interval edges agree with a fine independent scan, and one k agrees with the scan over k: "
          "cubic_bspline on triangular")
{
    CHECK(edges_against_independent_scan("cubic_bspline", "triangular", 0.8, 1.3, 10) == 3);
}

TEST_CASE("the same k gets the same verdict whatever the step count: the intervals agree to the bisection's width")
{
    const Kernel kernel = shipped_kernel("wendland_c2");
    const auto lattice = load_lattice("hcp");
    const auto a = stability_over_k(kernel, lattice, 1.890, 1.920, 3, gamma_53, 0, 1);
    const auto b = stability_over_k(kernel, lattice, 1.890, 1.920, 10, gamma_53, 0, 1);
    REQUIRE(a.stable.size() == b.stable.size());
    for (std::size_t i = 0; i < a.stable.size(); ++i) {
        CHECK(std::abs(a.stable[i].from - b.stable[i].from) <= 2 * stability_k_tolerance);
        CHECK(std::abs(a.stable[i].to - b.stable[i].to) <= 2 * stability_k_tolerance);
    }
}

TEST_CASE("hcp: the long-wave figure is the acoustic branches', finite, while an optical branch is unstable at Γ")
{
    const Kernel kernel = shipped_kernel("cubic_bspline");
    const auto lattice = load_lattice("hcp");
    const Dispersion d(kernel, lattice, 1.1, gamma_53);
    // An optical branch below zero at Γ: divided by kappa^2 it would be about -1e5 c^2.
    const Eigen::Vector3d n0 = Eigen::Vector3d(0.3, 0.2, 0.9).normalized();
    REQUIRE(d.omega2(1e-3 * n0).front() < -0.1);
    // Independently: omega^2 / kappa^2 at kappa = 1e-4 of the three modes whose sites move most in phase.
    auto acoustic = [&](const Eigen::Vector3d& n) {
        const auto modes = d.modes(1e-4 * n);
        std::vector<std::pair<double, double>> together; // (-in phase, omega^2 / kappa^2)
        for (int b = 0; b < d.branches(); ++b) {
            const auto& xi = modes.modes[static_cast<std::size_t>(b)];
            together.emplace_back(-(xi.segment(0, 3) + xi.segment(3, 3)).squaredNorm(),
                                  modes.omega2[static_cast<std::size_t>(b)] / 1e-8);
        }
        std::sort(together.begin(), together.end());
        return std::min({together[0].second, together[1].second, together[2].second});
    };
    double brute = INFINITY;
    for (int i = 0; i < 400; ++i) {
        const double z = 1 - (2.0 * i + 1) / 400, phi = i * M_PI * (3 - std::sqrt(5.0));
        brute =
            std::min(brute, acoustic({std::sqrt(1 - z * z) * std::cos(phi), std::sqrt(1 - z * z) * std::sin(phi), z}));
    }
    const auto found = long_wave_minimum(d);
    CHECK(std::isfinite(found.omega2_over_kappa2));
    CHECK(found.omega2_over_kappa2 == doctest::Approx(acoustic(found.direction)).epsilon(1e-5));
    CHECK(found.omega2_over_kappa2 <= brute + 1e-6);
    // The scan's fastest mode there is optical; the verdict is unstable.
    const auto scan = scan_brillouin_zone(d, reciprocal_lattice(lattice), 0, 1, false);
    CHECK(scan.verdict(default_horizon) == Verdict::unstable);
    CHECK(scan.mode.kind == ModeKind::optical);
    CHECK(scan.growth_time() == doctest::Approx(1 / std::sqrt(-scan.lowest().omega2)));
}

TEST_CASE("mode kinds: bcc's two-site cubic cell has no optical modes once unfolded, and one site: kappa and its "
          "polarisation")
{
    const Kernel kernel = shipped_kernel("wendland_c2");
    const auto bcc = load_lattice("bcc");
    const Dispersion d(kernel, bcc, 1.1, gamma_53);
    const auto reciprocal = reciprocal_lattice(bcc);
    // bcc is a Bravais lattice: every mode of the cubic cell is an acoustic mode at kappa + G.
    for (const Eigen::Vector3d& kappa : {Eigen::Vector3d(0.3, 0.1, 0.05), Eigen::Vector3d(1.2, -0.7, 2.1)})
        for (int b = 0; b < d.branches(); ++b) {
            const auto c = mode_character(d, reciprocal, kappa, b);
            CHECK(c.in_phase > 1 - 1e-9);
            CHECK(c.kind != ModeKind::optical);
            // The unfolded wave vector differs from kappa by a reciprocal vector of the cell.
            const Eigen::Vector3d m = reciprocal.vectors.inverse() * (c.unfolded - kappa);
            CHECK((m - m.array().round().matrix()).norm() < 1e-9);
        }
    // One site: the kind is the longitudinal fraction at kappa itself.
    const auto fcc = load_lattice("fcc");
    const Dispersion f(kernel, fcc, 1.1, gamma_53);
    const Eigen::Vector3d kappa(0.7, 0.2, -0.4);
    const auto modes = f.modes(kappa);
    for (int b = 0; b < 3; ++b) {
        const auto c = mode_character(f, reciprocal_lattice(fcc), kappa, b);
        CHECK(c.longitudinal == doctest::Approx(modes.longitudinal[static_cast<std::size_t>(b)]).epsilon(1e-9));
        CHECK((c.unfolded - kappa).norm() < 1e-15);
        CHECK((c.kind == ModeKind::longitudinal) == (modes.longitudinal[static_cast<std::size_t>(b)] > 0.5));
    }
}

TEST_CASE("the horizon: a slow instability is weak, listed with its growth time, and stable at the horizon")
{
    // morris_quintic on fcc at k = 0.892: a transverse mode grows in about 330 d/c.
    const Kernel kernel = shipped_kernel("morris_quintic");
    const auto lattice = load_lattice("fcc");
    const auto scan =
        scan_brillouin_zone(Dispersion(kernel, lattice, 0.892, gamma_53), reciprocal_lattice(lattice), 0, 1);
    REQUIRE_FALSE(scan.stable);
    const double tau = scan.growth_time();
    CHECK(tau == doctest::Approx(1 / std::sqrt(-scan.lowest().omega2)));
    CHECK(scan.verdict(tau * 0.9) == Verdict::weak);
    CHECK(scan.verdict(tau * 1.1) == Verdict::unstable);
    const auto over_k = stability_over_k(kernel, lattice, 0.885, 0.900, 3, gamma_53, 0, 1, tau * 0.9);
    CHECK_FALSE(inside(over_k.stable, 0.892));
    CHECK(inside(over_k.usable, 0.892));
}

TEST_CASE(
    "the spectrum's symmetries are the crystal point groups, and a grid filled in by them is the grid computed in full")
{
    const Kernel kernel = shipped_kernel("cubic_bspline");
    // Oh (48) for sc, fcc and bcc written as a cubic cell; D6h (24) for hcp and the hexagonal
    // prism; C6v (12) for the triangular lattice, C4v (8) for the square one.
    const std::pair<const char*, std::size_t> groups[] = {{"sc", 48},   {"fcc", 48},       {"bcc", 48},
                                                          {"hcp", 24},  {"hex_prism", 24}, {"triangular", 12},
                                                          {"square", 8}};
    for (const auto& [name, order] : groups) {
        const std::string lattice_name = name;
        CAPTURE(lattice_name);
        const auto lattice = load_lattice(name);
        const Dispersion d(kernel, lattice, 1.3, gamma_53);
        const auto reciprocal = reciprocal_lattice(lattice);
        const auto symmetries = zone_symmetries(d, reciprocal);
        CHECK(symmetries.size() == order);
        const ZoneGrid grid(d, reciprocal.vectors, 6, symmetries, 1);
        CHECK(grid.evaluated() < grid.size());
        double worst = 0, scale = 0;
        for (std::size_t i = 0; i < grid.size(); ++i) {
            const double direct = d.omega2(reciprocal.vectors * grid.fraction(i)).front();
            worst = std::max(worst, std::abs(grid.lowest(i) - direct));
            scale = std::max(scale, std::abs(direct));
        }
        CAPTURE(scale);
        // The closed-form 3 x 3 eigenvalues lose about half their digits where two coincide
        // (high-symmetry points), so images agree to ~1e-8 of the scale there, not to rounding.
        CHECK(worst < 1e-7 * scale);
    }
}
