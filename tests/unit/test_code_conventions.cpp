// sphkern's k as other codes set it: SWIFT's kernel gamma against the values SWIFT lists, and
// each code's parameter against its definition written out for the sc lattice.
#include "codes/code_table.hpp"
#include "codes/swift/swift_gamma.hpp"
#include "helpers.hpp"
#include "requests/eps_request.hpp"
#include "requests/surface_request.hpp"
#include "stability/recommended_k.hpp"
#include "support/error.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace sphkern;
using namespace sphkern::test;

TEST_CASE("SWIFT's kernel gamma H / (2 sigma) is the value SWIFT lists for its 3D kernels")
{
    // SWIFT's kernel_hydro.h, 3D: cubic, quartic and quintic spline, Wendland C2, C4, C6.
    const std::pair<const char*, double> listed[] = {{"cubic_bspline", 1.825742},  {"quartic_bspline", 2.018932},
                                                     {"morris_quintic", 2.195775}, {"wendland_c2", 1.936492},
                                                     {"wendland_c4", 2.207940},    {"wendland_c6", 2.449490}};
    for (const auto& [name, gamma] : listed) {
        CAPTURE(name);
        CHECK(swift_gamma(shipped_kernel(name), 3) == doctest::Approx(gamma).epsilon(1e-6));
    }
}

TEST_CASE("each code's parameter at the rest density follows from h = k d and H = R h, and SWIFT's eta 1.2348 with the "
          "cubic spline is GADGET's 48 neighbours")
{
    const Kernel cubic = shipped_kernel("cubic_bspline"); // R = 2
    const double k = 1.3, a_p = 1;                        // sc: dp = d
    const double H = 2 * k;
    const auto source = ValueSource::option("--code");
    auto at_rest = [&](const char* code, int dim, double ap, double kk) {
        return code_parameter(code_profile(code, source), cubic, dim, ap, kk, 0);
    };
    CHECK(at_rest("pysph", 3, a_p, k) == doctest::Approx(k));
    CHECK(at_rest("phantom", 3, a_p, k) == doctest::Approx(k));
    CHECK(at_rest("dualsphysics", 3, a_p, k) == doctest::Approx(H / (2 * std::sqrt(3.0))));
    CHECK(at_rest("splishsplash", 3, a_p, k) == doctest::Approx(H / 4));
    CHECK(at_rest("gadget2", 3, a_p, k) == doctest::Approx(4 * M_PI / 3 * H * H * H));
    CHECK(at_rest("gadget2", 2, a_p, k) == doctest::Approx(M_PI * H * H));
    // SWIFT's default eta = 1.2348 gives about 48 neighbours (its documentation): the same k both ways.
    const double swift_k = 1.2348 * 1.825742 / 2; // H = gamma eta dp = R k d
    CHECK(at_rest("swift", 3, a_p, swift_k) == doctest::Approx(1.2348).epsilon(1e-6));
    CHECK(at_rest("gadget2", 3, a_p, swift_k) == doctest::Approx(48.0).epsilon(1e-3));
    // A volume coefficient scales the spacing: dp = a_p^(1/D) d.
    CHECK(at_rest("pysph", 3, 0.5, k) == doctest::Approx(k / std::cbrt(0.5)));
    CHECK_THROWS_AS(code_profile("nosuch", source), Error);
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

namespace {

// The SPH density at a site of a lattice by a direct sum over its points (self included),
// with m = a_p (rho0 = 1) and W(r, h) = w(r / h) / h^D.
double brute_density(const Kernel& kernel, const Lattice& lattice, double a_p, double h)
{
    const int reach = static_cast<int>(kernel.support() * h) + 3, dim = lattice.dimension;
    double sum = 0;
    for (int i = -reach; i <= reach; ++i)
        for (int j = -reach; j <= reach; ++j)
            for (int l = (dim == 3 ? -reach : 0); l <= (dim == 3 ? reach : 0); ++l)
                for (const auto& s : lattice.motif) {
                    const double r = (lattice.basis * (Eigen::Vector3d(i, j, l) + s - lattice.motif[0])).norm();
                    if (r < kernel.support() * h) sum += kernel.w(r / h, dim, h) / std::pow(h, dim);
                }
    return a_p * sum;
}

} // namespace

TEST_CASE("a code's own setting gives the k at which that code's definition holds, with its own SPH density")
{
    const auto lattice = load_lattice("fcc");
    const double a_p = lattice.volume_coefficient("voronoi"), m = a_p; // rho0 = 1, d = 1
    struct Case {
        const char* code;
        const char* kernel;
        double value;
    };
    const Case cases[] = {{"swift", "wendland_c2", 1.2348}, {"phantom", "wendland_c2", 1.2},
                          {"gadget2", "cubic_bspline", 48}, {"gadget4", "wendland_c2", 100},
                          {"pysph", "wendland_c2", 1.2},    {"dualsphysics", "wendland_c2", 1.0}};
    for (const auto& c : cases) {
        CAPTURE(c.code);
        const auto kernel = shipped_kernel(c.kernel);
        EpsRequest request;
        request.code = CodeSetting{c.code, c.value};
        const EpsSources sources{ValueSource::option("--k"),
                                 ValueSource::option("--axis"),
                                 {},
                                 ValueSource::option("--code"),
                                 ValueSource::option("--x")};
        check_eps_request(request, sources);
        const double k = run_eps_at_k(request, sources, kernel, lattice).k;
        // Each definition written out at that k (the support H = 2 k for both kernels).
        const double H = 2 * k, rho = brute_density(kernel, lattice, a_p, k), dx = std::cbrt(a_p);
        const std::string code = c.code;
        double value = 0;
        if (code == "swift") value = H / std::sqrt(15.0 / 4) / std::cbrt(m / rho); // SWIFT's gamma of Wendland C2 in 3D
        if (code == "phantom") value = (H / 2) / std::cbrt(m / rho);               // radkern = 2
        if (code == "gadget2" || code == "gadget4") value = 4 * M_PI / 3 * H * H * H * rho / m;
        if (code == "pysph") value = (H / 2) / dx;                           // radius_scale = 2
        if (code == "dualsphysics") value = (H / 2) / (std::sqrt(3.0) * dx); // support 2 h
        CHECK(value == doctest::Approx(c.value).epsilon(1e-10));
    }
    // The density the codes solve with is not rho0: SWIFT's eta 1.2348 with Wendland C2 on fcc is
    // another k than the one at rest, and its eps_rho fails condition (22).
    EpsRequest swift;
    swift.code = CodeSetting{"swift", 1.2348};
    const auto at = run_eps_at_k(swift,
                                 {ValueSource::option("--k"),
                                  ValueSource::option("--axis"),
                                  {},
                                  ValueSource::option("--code"),
                                  ValueSource::option("--eta")},
                                 shipped_kernel("wendland_c2"), lattice);
    CHECK(std::abs(at.k - 1.2348 * std::sqrt(15.0 / 4) * std::cbrt(a_p) / 2) > 1e-3);
    CHECK(std::abs(at.chosen().eps_rho) > 0.01);
    // A kernel the code does not ship is refused, listing those it does.
    EpsRequest gadget;
    gadget.code = CodeSetting{"gadget2", 48};
    CHECK_THROWS_WITH(run_eps_at_k(gadget,
                                   {ValueSource::option("--k"),
                                    ValueSource::option("--axis"),
                                    {},
                                    ValueSource::option("--code"),
                                    ValueSource::option("--nngb")},
                                   shipped_kernel("wendland_c2"), lattice),
                      "wendland_c2: gadget2 does not ship it; its kernels are cubic_bspline");
}

TEST_CASE("surface --code: the profile at the k where the code's definition holds for the bulk's own SPH density")
{
    const auto lattice = load_lattice("fcc");
    const double a_p = lattice.volume_coefficient("voronoi"), m = a_p;
    const auto kernel = shipped_kernel("wendland_c2");
    SurfaceRequest request;
    request.code = CodeSetting{"swift", 1.2348};
    request.layers = 12;
    const SurfaceSources sources{ValueSource::option("--k"),
                                 {},
                                 ValueSource::option("--layers"),
                                 ValueSource::option("--code"),
                                 ValueSource::option("--eta")};
    check_surface_request(request, sources);
    const auto result = run_surface(request, sources, kernel, lattice);
    REQUIRE(result.code);
    // SWIFT's eta written out at that k: H = 2 k = gamma h_s with Wendland C2's gamma sqrt(15/4) in 3D.
    const double k = result.k, rho = brute_density(kernel, lattice, a_p, k);
    CHECK(2 * k / std::sqrt(15.0 / 4) / std::cbrt(m / rho) == doctest::Approx(1.2348).epsilon(1e-10));
    // Deep below the surface, the bulk at that k.
    const auto brute = brute_force_errors(kernel, lattice, k, a_p, lattice.gravity);
    CHECK(result.profile.bulk.sites[0].eps_rho == doctest::Approx(brute.eps_rho).epsilon(1e-10));
    // The code's parameter without --code, or a value it cannot take, is refused naming the option.
    SurfaceRequest bad = request;
    bad.code->value = -1;
    CHECK_THROWS_WITH(check_surface_request(bad, sources), "--eta -1: expected a number in (0, 100]");
}
