// The typed requests of eps, roots, surface, design, spectrum, check, block and stability: each refusal names its
// source (the command line's option or Python's argument) and keeps its exit code; a good request's result equals an
// independent brute-force lattice sum.
#include "helpers.hpp"

#include "requests/block_request.hpp"
#include "requests/check_request.hpp"
#include "requests/design_request.hpp"
#include "requests/eps_request.hpp"
#include "requests/roots_request.hpp"
#include "requests/spectrum_request.hpp"
#include "requests/stability_request.hpp"
#include "requests/surface_request.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>

using namespace sphkern;
using test::refusal;

namespace {

EvaluationSources option_evaluation(const std::string& shells)
{
    return {ValueSource::option("--gravity"), {"--site", ExitCode::input}, ValueSource::option("--shells " + shells)};
}

EpsSources eps_options(const std::string& shells = "")
{
    return {ValueSource::option("--k"), ValueSource::option("--axis"), option_evaluation(shells), {}, {}};
}

EpsSources eps_arguments()
{
    return {ValueSource::argument("k"),
            ValueSource::argument("axis"),
            {ValueSource::argument("gravity"), ValueSource::argument("site"), ValueSource::argument("shells")},
            {},
            {}};
}

EpsRequest eps_at(std::vector<double> k)
{
    EpsRequest r;
    r.k = std::move(k);
    return r;
}

} // namespace

TEST_CASE("eps request: each bad value is refused naming its option or argument")
{
    auto k = refusal([] { check_eps_request(eps_at({-1}), eps_options()); });
    CHECK(k.first == "--k -1 is not allowed, expected a number in (0, 100]");
    CHECK(k.second == ExitCode::usage);
    auto k_argument = refusal([] { check_eps_request(eps_at({1, 200}), eps_arguments()); });
    CHECK(k_argument.first == "k = 200 is not allowed, expected a number in (0, 100]");
    CHECK(k_argument.second == ExitCode::input);
    auto nan = refusal([] { check_eps_request(eps_at({std::numeric_limits<double>::quiet_NaN()}), eps_arguments()); });
    CHECK(nan.first == "k = nan is not allowed, expected a number in (0, 100]");
    CHECK(refusal([] { check_eps_request(eps_at({}), eps_arguments()); }).first == "k: an empty array");
    auto window = eps_at({30});
    window.axis = Axis::nh;
    auto nh = refusal([&] { check_eps_request(window, eps_options()); });
    CHECK(nh.first == "--axis nh names a window, not one value: give --k on the k or h_over_l axis");
    CHECK(nh.second == ExitCode::input);
    auto shells = eps_at({1});
    shells.evaluation.shell_radii = {1, -1};
    auto radius = refusal([&] { check_eps_request(shells, eps_options("1,-1")); });
    CHECK(radius.first == "--shells 1,-1: \"-1\" is not a positive number");
    CHECK(radius.second == ExitCode::usage);
    CHECK_NOTHROW(check_eps_request(eps_at({0.5, 1, 100}), eps_arguments()));
}

TEST_CASE("eps request: the values that need the lattice are refused naming their source")
{
    const auto kernel = test::shipped_kernel("cubic_bspline");
    const auto lattice = load_lattice("fcc");
    auto site = eps_at({1.2});
    site.evaluation.site = 5;
    CHECK(refusal([&] { run_eps_at_k(site, eps_options(), kernel, lattice); }).first ==
          "--site: site 5 does not exist; lattice fcc has sites 0 to 0");
    auto gravity = eps_at({1.2});
    gravity.evaluation.gravity = std::vector<double>{0, 0, 0};
    auto zero = refusal([&] { run_eps_series(gravity, eps_arguments(), kernel, lattice); });
    CHECK(zero.first == "gravity: expected a direction: finite components, not all zero");
    CHECK(zero.second == ExitCode::input);
    gravity.evaluation.gravity = std::vector<double>{0, 1};
    CHECK(refusal([&] { run_eps_at_k(gravity, eps_options(), kernel, lattice); }).first ==
          "--gravity: 2 components, expected 3 (one per dimension)");
    auto a_p = eps_at({1.2});
    a_p.evaluation.a_p = -1.0;
    CHECK(refusal([&] { run_eps_series(a_p, eps_arguments(), kernel, lattice); }).first ==
          "volume coefficient a_p = -1 is not allowed, expected a positive number up to 1e6");
    a_p.evaluation.a_p = std::string("hexagon");
    CHECK(refusal([&] {
              run_eps_at_k(a_p, eps_options(), kernel, lattice);
          }).first.find("lattice fcc has no volume coefficient \"hexagon\"") == 0);
    auto eta = eps_at({60});
    eta.axis = Axis::eta;
    eta.evaluation.a_p = 8.0; // k = eta a_p^(1/3) = 120
    auto far = refusal([&] { run_eps_at_k(eta, eps_options(), kernel, lattice); });
    CHECK(far.first == "k = 120 is not allowed, expected a number in (0, 100] (--k 60 on the h_over_l axis)");
    CHECK(far.second == ExitCode::input);
}

TEST_CASE("eps request: the errors at one k and along k equal a brute-force lattice sum")
{
    const auto kernel = test::shipped_kernel("cubic_bspline");
    for (const char* name : {"fcc", "triangular"}) {
        CAPTURE(name);
        const auto lattice = load_lattice(name);
        const double a_p = lattice.volume_per_site(); // voronoi
        const auto at_k = run_eps_at_k(eps_at({1.2}), eps_options(), kernel, lattice);
        const auto brute = test::brute_force_errors(kernel, lattice, 1.2, a_p, lattice.gravity);
        CHECK(at_k.k == 1.2);
        CHECK(at_k.a_p == doctest::Approx(a_p).epsilon(1e-14));
        CHECK(at_k.chosen().eps_rho == doctest::Approx(brute.eps_rho).epsilon(1e-10));
        CHECK(at_k.chosen().eps_gradp == doctest::Approx(brute.eps_gradp).epsilon(1e-10));
        CHECK(at_k.support_radius == doctest::Approx(2 * 1.2)); // the cubic B-spline reaches q = 2
        const std::vector<double> ks = {0.9, 1.05, 1.3};
        const auto series = run_eps_series(eps_at(ks), eps_arguments(), kernel, lattice);
        REQUIRE(series.size() == ks.size());
        for (std::size_t i = 0; i < ks.size(); ++i) {
            const auto b = test::brute_force_errors(kernel, lattice, ks[i], a_p, lattice.gravity);
            CHECK(series[i].eps_rho == doctest::Approx(b.eps_rho).epsilon(1e-10));
            CHECK(series[i].eps_gradp == doctest::Approx(b.eps_gradp).epsilon(1e-10));
        }
    }
}

TEST_CASE("eps request: k given on the eta axis is eta a_p^(1/D)")
{
    const auto kernel = test::shipped_kernel("cubic_bspline");
    const auto lattice = load_lattice("fcc");
    auto request = eps_at({1.1});
    request.axis = Axis::eta;
    request.evaluation.a_p = 0.5;
    const auto result = run_eps_at_k(request, eps_options(), kernel, lattice);
    CHECK(result.k == doctest::Approx(1.1 * std::cbrt(0.5)).epsilon(1e-14));
    CHECK(result.eta == doctest::Approx(1.1).epsilon(1e-14));
    const auto brute = test::brute_force_errors(kernel, lattice, result.k, 0.5, lattice.gravity);
    CHECK(result.chosen().eps_rho == doctest::Approx(brute.eps_rho).epsilon(1e-10));
}

namespace {

RootsSources roots_options()
{
    return {ValueSource::argument("--kmin/--kmax"), ValueSource::option("--epsilon"), ValueSource::option("--gamma"),
            ValueSource::option("--horizon"),       ValueSource::option("--steps"),   option_evaluation("")};
}

RootsSources roots_arguments()
{
    return {ValueSource::argument("kmin/kmax"),
            ValueSource::argument("epsilon"),
            ValueSource::argument("gamma"),
            ValueSource::argument("horizon"),
            ValueSource::argument("steps"),
            {ValueSource::argument("gravity"), ValueSource::argument("site"), ValueSource::argument("shells")}};
}

} // namespace

TEST_CASE("roots request: each bad value is refused naming its option or argument")
{
    RootsRequest window;
    window.window_min = 1.2;
    window.window_max = 0.8;
    auto k = refusal([&] { check_roots_request(window, roots_options()); });
    CHECK(k.first == "--kmin/--kmax: [1.2, 0.8] is not allowed, expected 0 < min < max <= 100");
    CHECK(k.second == ExitCode::input);
    window.axis = Axis::nh; // a window in neighbours is checked against the lattice
    CHECK_NOTHROW(check_roots_request(window, roots_options()));
    RootsRequest epsilon;
    epsilon.epsilon = 2;
    auto option = refusal([&] { check_roots_request(epsilon, roots_options()); });
    CHECK(option.first == "--epsilon must be in (0, 1)");
    CHECK(option.second == ExitCode::usage);
    auto argument = refusal([&] { check_roots_request(epsilon, roots_arguments()); });
    CHECK(argument.first == "epsilon must be in (0, 1)");
    CHECK(argument.second == ExitCode::input);
    RootsRequest gamma;
    gamma.model.gamma = 0;
    CHECK(refusal([&] { check_roots_request(gamma, roots_arguments()); }).first ==
          "gamma 0 is not allowed, expected a number in [1e-06, 1e+06]");
    RootsRequest horizon;
    horizon.model.horizon = -1;
    CHECK(refusal([&] { check_roots_request(horizon, roots_options()); }).first.find("--horizon") == 0);
    RootsRequest steps;
    steps.model.steps = 0;
    CHECK(refusal([&] { check_roots_request(steps, roots_arguments()); }).first == "steps = 0, expected 1 to 2000");
    RootsRequest site;
    site.evaluation.site = 3;
    CHECK(refusal([&] {
              run_roots(site, roots_arguments(), test::shipped_kernel("cubic_bspline"), load_lattice("fcc"));
          }).first == "site: site 3 does not exist; lattice fcc has sites 0 to 0");
}

TEST_CASE("roots request: every root found is a zero of the brute-force lattice sum")
{
    const auto kernel = test::shipped_kernel("cubic_bspline");
    const auto lattice = load_lattice("fcc");
    const double a_p = lattice.volume_per_site();
    RootsRequest request;
    request.window_min = 0.75;
    request.window_max = 1.6;
    check_roots_request(request, roots_options());
    const auto result = run_roots(request, roots_options(), kernel, lattice);
    CHECK(result.k_min == 0.75);
    CHECK(result.k_max == 1.6);
    const auto& roots = result.analysis.sites.at(0).scan.roots;
    REQUIRE(!roots.empty());
    for (const auto& root : roots) {
        CAPTURE(root.k);
        const auto brute = test::brute_force_errors(kernel, lattice, root.k, a_p, lattice.gravity);
        const double value = root.function == ErrorFunction::rho ? brute.eps_rho : brute.eps_gradp;
        CHECK(std::abs(value) < 1e-8);
        // A sign change: the brute-force sum changes sign across the root.
        const auto left = test::brute_force_errors(kernel, lattice, root.k - 1e-4, a_p, lattice.gravity);
        const auto right = test::brute_force_errors(kernel, lattice, root.k + 1e-4, a_p, lattice.gravity);
        const bool rho = root.function == ErrorFunction::rho;
        CHECK((rho ? left.eps_rho * right.eps_rho : left.eps_gradp * right.eps_gradp) < 0);
    }
}

TEST_CASE("surface request: k and the values that need the lattice are refused naming their source")
{
    const auto kernel = test::shipped_kernel("cubic_bspline");
    const auto lattice = load_lattice("fcc");
    const EvaluationSources evaluation{ValueSource::argument("gravity"), ValueSource::argument("site"),
                                       ValueSource::argument("shells")};
    SurfaceRequest bad_k;
    bad_k.k = -1;
    auto k = refusal([&] {
        check_surface_request(bad_k, {ValueSource::argument("k"), evaluation, ValueSource::argument("layers"),
                                      ValueSource::argument("code"), ValueSource::argument("value")});
    });
    CHECK(k.first == "k = -1 is not allowed, expected a number in (0, 100]");
    CHECK(k.second == ExitCode::input);
    SurfaceRequest gravity;
    gravity.k = 1.2;
    gravity.evaluation.gravity = std::vector<double>{0, 0, 0};
    CHECK_NOTHROW(
        check_surface_request(gravity, {ValueSource::argument("k"), evaluation, ValueSource::argument("layers"),
                                        ValueSource::argument("code"), ValueSource::argument("value")}));
    CHECK(refusal([&] {
              run_surface(gravity,
                          {ValueSource::argument("k"), evaluation, ValueSource::argument("layers"),
                           ValueSource::argument("code"), ValueSource::argument("value")},
                          kernel, lattice);
          }).first == "gravity: expected a direction: finite components, not all zero");
    // The request names the site, not the profile in its own words.
    SurfaceRequest site;
    site.k = 1.2;
    site.evaluation.site = 3;
    auto missing = refusal([&] {
        run_surface(site,
                    {ValueSource::argument("k"), evaluation, ValueSource::argument("layers"),
                     ValueSource::argument("code"), ValueSource::argument("value")},
                    kernel, lattice);
    });
    CHECK(missing.first == "site: site 3 does not exist; lattice fcc has sites 0 to 0");
    CHECK(missing.second == ExitCode::input);
    auto option = refusal([&] {
        check_surface_request(bad_k, {ValueSource::option("--k"), evaluation, ValueSource::option("--layers"),
                                      ValueSource::option("--code"), ValueSource::option("--eta")});
    });
    CHECK(option.first == "--k -1 is not allowed, expected a number in (0, 100]");
    CHECK(option.second == ExitCode::usage);
    SurfaceRequest layers = gravity;
    layers.layers = 10001;
    auto too_many = refusal([&] {
        check_surface_request(layers, {ValueSource::argument("k"), evaluation, ValueSource::argument("layers"),
                                       ValueSource::argument("code"), ValueSource::argument("value")});
    });
    CHECK(too_many.first == "layers = 10001, expected 1 to 10000");
    CHECK(too_many.second == ExitCode::input);
}

TEST_CASE("surface request: deep below the surface the errors are the bulk's brute-force sum")
{
    const auto kernel = test::shipped_kernel("cubic_bspline");
    for (const char* name : {"fcc", "square"}) {
        CAPTURE(name);
        const auto lattice = load_lattice(name);
        SurfaceRequest request;
        request.k = 1.2;
        request.layers = 16; // past 2 R k = 4.8 d on both lattices
        request.evaluation.a_p = 0.9;
        const SurfaceSources sources{ValueSource::argument("k"),
                                     {ValueSource::argument("gravity"), ValueSource::argument("site"),
                                      ValueSource::argument("shells")},
                                     ValueSource::option("--layers"),
                                     ValueSource::option("--code"),
                                     ValueSource::option("--eta")};
        check_surface_request(request, sources);
        SurfaceRequest none = request;
        none.layers = 0;
        CHECK(refusal([&] { check_surface_request(none, sources); }).first == "--layers 0, expected 1 to 10000");
        const auto result = run_surface(request, sources, kernel, lattice);
        CHECK(result.a_p == 0.9);
        const auto brute = test::brute_force_errors(kernel, lattice, 1.2, 0.9, lattice.gravity);
        REQUIRE(result.profile.bulk.sites.size() == 1);
        CHECK(result.profile.bulk.sites[0].eps_rho == doctest::Approx(brute.eps_rho).epsilon(1e-10));
        CHECK(result.profile.bulk.sites[0].eps_gradp == doctest::Approx(brute.eps_gradp).epsilon(1e-10));
        // A layer deeper than twice the support radius H = R k has every neighbour, and so
        // has each of its neighbours (the Monaghan form reads their densities): its sums run
        // over the brute-force bulk's neighbours, only in another order. Both errors are sums
        // of under a hundred terms of order 1, so rounding stays below 1e-13; 1e-10 leaves room
        // for that, while a neighbour missing inside 0.99 H would shift eps_rho by over 1e-7.
        const double complete = 2 * kernel.support() * request.k;
        int deep = 0;
        for (const auto& layer : result.profile.layers) {
            if (layer.depth <= complete + 1e-9) continue;
            CAPTURE(layer.n);
            ++deep;
            for (const auto& v : layer.sites) {
                CHECK(std::abs(v.eps_rho - brute.eps_rho) < 1e-10);
                CHECK(std::abs(v.eps_gradp - brute.eps_gradp) < 1e-10);
            }
        }
        CHECK(deep >= 2);
        // The top layer misses the neighbours above it: its density error is far below the bulk's.
        REQUIRE(!result.profile.layers.empty());
        CHECK(result.profile.layers.front().sites.at(0).eps_rho < brute.eps_rho - 0.1);
    }
}

TEST_CASE("design request: a bad window is refused naming it, and each solution is a zero of both brute-force sums")
{
    const DesignSources arguments{ValueSource::argument("kmin/kmax"),
                                  {ValueSource::argument("gravity"), ValueSource::argument("site"),
                                   ValueSource::argument("shells")}};
    DesignRequest window;
    window.k_min = 2;
    window.k_max = 1;
    auto k = refusal([&] { check_design_request(window, arguments); });
    CHECK(k.first == "kmin/kmax: [2, 1] is not allowed, expected 0 < min < max <= 100");
    CHECK(k.second == ExitCode::input);
    const auto lattice = load_lattice("triangular");
    DesignRequest site;
    site.parameter = "alpha";
    site.evaluation.site = 3;
    const Kernel spiky_blend(test::shipped_kernels().find("cubic_bspline+desbrun_spiky"));
    auto missing = refusal([&] { run_design(site, arguments, spiky_blend, lattice); });
    CHECK(missing.first == "site: site 3 does not exist; lattice triangular has sites 0 to 0");
    CHECK(missing.second == ExitCode::input);
    const Kernel blend(test::shipped_kernels().find("cubic_bspline+desbrun_spiky"));
    DesignRequest request;
    request.parameter = "alpha";
    request.range = std::pair(-1.0, 2.0);
    request.evaluation.a_p = std::string("voronoi");
    check_design_request(request, arguments);
    const auto outcome = run_design(request, arguments, blend, lattice);
    CHECK(outcome.problem.a_p == doctest::Approx(lattice.volume_per_site()).epsilon(1e-14));
    REQUIRE(!outcome.result.solutions.empty());
    for (const auto& s : outcome.result.solutions) {
        const Kernel designed(blend.shared_definition(), {{"alpha", s.parameter}});
        const auto brute = test::brute_force_errors(designed, lattice, s.k, outcome.problem.a_p, lattice.gravity);
        CHECK(std::abs(brute.eps_rho) < 1e-9);
        CHECK(std::abs(brute.eps_gradp) < 1e-9);
    }
}

namespace {

const SpectrumSources spectrum_options{ValueSource::option("--dim"), ValueSource::option("--k"),
                                       ValueSource::option("--max"), ValueSource::option("--points")};

SpectrumRequest spectrum_in(int dimension)
{
    SpectrumRequest r;
    r.dimension = dimension;
    return r;
}

} // namespace

TEST_CASE("spectrum request: each value out of range is refused naming its option")
{
    auto dimension = refusal([] { check_spectrum_request(spectrum_in(4), spectrum_options); });
    CHECK(dimension.first == "--dim 4, expected 1 to 3");
    CHECK(dimension.second == ExitCode::usage);
    auto points = spectrum_in(3);
    points.points = 0;
    CHECK(refusal([&] { check_spectrum_request(points, spectrum_options); }).first ==
          "--points 0, expected 1 to 100000");
    auto kh_max = spectrum_in(3);
    kh_max.kh_max = std::numeric_limits<double>::quiet_NaN();
    CHECK(refusal([&] { check_spectrum_request(kh_max, spectrum_options); }).first ==
          "--max nan, expected 0.1 to 1000");
    auto k = spectrum_in(3);
    k.k = 200;
    CHECK(refusal([&] { check_spectrum_request(k, spectrum_options); }).first == "--k 200, expected 0.001 to 100");
    CHECK(refusal([] { run_spectrum(spectrum_in(3), spectrum_options, test::shipped_kernel("composite")); }).first ==
          "kernel composite is defined in 2D only, not on the 3D lattice (--dim 3)");
}

TEST_CASE("spectrum request: the cubic B-spline's 1D transform is sinc^4(kappa h / 2)")
{
    // Four boxes of width h convolved: each transforms to sin(kappa h / 2) / (kappa h / 2).
    auto request = spectrum_in(1);
    request.kh_max = 20;
    request.points = 40;
    check_spectrum_request(request, spectrum_options);
    const auto result = run_spectrum(request, spectrum_options, test::shipped_kernel("cubic_bspline"));
    REQUIRE(result.curve.size() == 41);
    for (const auto& [kh, value] : result.curve) {
        CAPTURE(kh);
        const double x = kh / 2, sinc = x == 0 ? 1 : std::sin(x) / x;
        CHECK(value == doctest::Approx(std::pow(sinc, 4)).epsilon(1e-6).scale(1));
    }
    // Its minimum, 0, is touched (not crossed) at every multiple of 2 pi.
    CHECK(result.summary.minimum == doctest::Approx(0).scale(1).epsilon(1e-9));
    CHECK(std::abs(std::remainder(result.summary.at, 2 * M_PI)) < 1e-3);
}

TEST_CASE("check request: nothing to check is refused, and the verdict is a status, strict counts a warning")
{
    const CheckSources sources = check_sources(FrontEnd::command_line);
    auto nothing = refusal([&] { check_check_request(CheckRequest{}, sources); });
    CHECK(nothing.first == "check: name a kernel, give --plugin FILE, or use --all");
    CHECK(nothing.second == ExitCode::usage);
    auto in_python = refusal([&] { check_check_request(CheckRequest{}, check_sources(FrontEnd::python)); });
    CHECK(in_python.first == "check: name a kernel, give plugin=FILE, or use all=True");
    CHECK(in_python.second == ExitCode::input);
    CheckRequest slow;
    slow.names = {"cubic_bspline"};
    slow.timeout = 0;
    auto timeout = refusal([&] { check_check_request(slow, sources); });
    CHECK(timeout.first == "--timeout 0, expected 0.1 to 3600");
    CHECK(timeout.second == ExitCode::usage);
    CHECK(check_status_named("warn") == CheckStatus::warn);
    CHECK(std::string(check_status_name(CheckStatus::fail)) == "fail");
    CHECK(refusal([] { check_status_named("fine"); }).second == ExitCode::plugin);
    CheckRequest request;
    // Wendland's C2 function is positive definite up to 3D (Wendland 1995): every check
    // passes. (The cubic B-spline warns: its 2D and 3D transforms go negative.)
    request.names = {"wendland_c2", "super_gaussian"};
    check_check_request(request, sources);
    auto registry = check_registry(request);
    const auto kernels = kernels_to_check(request, registry);
    REQUIRE(kernels.size() == 2);
    const auto fine = run_check(request, kernels[0]);
    CHECK(fine.verdict == CheckStatus::ok);
    CHECK(fine.document["verdict"] == "ok");
    CHECK_FALSE(check_fails(fine, true));
    // The 2D super-Gaussian's second moment is negative: a warning.
    const auto warned = run_check(request, kernels[1]);
    CHECK(warned.verdict == CheckStatus::warn);
    CHECK_FALSE(check_fails(warned, false));
    CHECK(check_fails(warned, true));
}

TEST_CASE(
    "block request: sizes are refused naming the option, and deep inside a periodic block the errors are the bulk's")
{
    const BlockSources sources{ValueSource::option("--size 10,10"), ValueSource::option("--threads"),
                               ValueSource::option("--k")};
    const auto kernel = test::shipped_kernel("cubic_bspline");
    BlockRequest request;
    request.k = -1;
    request.cells = {10, 10, 10};
    auto k = refusal([&] { check_block_request(request, sources); });
    CHECK(k.first == "--k -1 is not allowed, expected a number in (0, 100]");
    CHECK(k.second == ExitCode::usage);
    request.k = 1.2;
    request.cells = {1, 2, 3, 4};
    CHECK(refusal([&] { check_block_request(request, sources); }).first ==
          "--size 10,10: expected N1,N2[,N3] integers");
    request.cells = {10, 10};
    check_block_request(request, sources);
    auto dimension = refusal([&] { run_block(request, sources, kernel, load_lattice("fcc")); });
    CHECK(dimension.first == "--size 10,10: the lattice is 3D, expected 3 cell counts");
    CHECK(dimension.second == ExitCode::input); // a value that does not fit the lattice
    request.threads = -1;
    CHECK(refusal([&] { check_block_request(request, sources); }).first == "--threads -1, expected 0 to 1024");
    // sc, layers d apart, support 2.4 d: layers 3 to 6 of 10 see complete neighbourhoods.
    const auto lattice = load_lattice("sc");
    request = BlockRequest{};
    request.k = 1.2;
    request.cells = {8, 8, 10};
    request.periodic = true;
    request.threads = 1;
    const auto run = run_block(request, sources, kernel, lattice);
    CHECK(run.result.particles() == 640);
    CHECK(run.options.a_p == 1.0); // the voronoi volume of sc
    const auto bulk = test::brute_force_errors(kernel, lattice, 1.2, 1.0, run.result.gravity);
    int deep = 0;
    for (const auto& l : run.result.layers()) {
        if (l.layer < 3 || l.layer > 6) continue;
        CAPTURE(l.layer);
        ++deep;
        CHECK(l.rho_min == doctest::Approx(bulk.eps_rho).epsilon(1e-10).scale(1));
        CHECK(l.rho_max == doctest::Approx(bulk.eps_rho).epsilon(1e-10).scale(1));
        CHECK(l.gradp_min == doctest::Approx(bulk.eps_gradp).epsilon(1e-10).scale(1));
        CHECK(l.gradp_max == doctest::Approx(bulk.eps_gradp).epsilon(1e-10).scale(1));
    }
    CHECK(deep == 4);
}

namespace {

StabilitySources stability_sources(bool options)
{
    auto named = [&](const std::string& name) {
        return options ? ValueSource::option("--" + name) : ValueSource::argument(name);
    };
    return {named("k"),          named("kmin"),  named("kmax"), named("gamma"), named("horizon"),
            named("wavevector"), named("steps"), named("grid"), named("path"),  ""};
}

} // namespace

TEST_CASE("stability request: ranges and which values go together are refused naming their source")
{
    StabilityRequest at_k;
    at_k.k = 1.2;
    CHECK_NOTHROW(check_stability_request(at_k, stability_sources(true)));
    CHECK(stability_mode(at_k) == StabilityMode::zone_scan);
    auto steps = at_k;
    steps.steps = 0;
    CHECK(refusal([&] { check_stability_request(steps, stability_sources(false)); }).first ==
          "steps = 0, expected 1 to 2000");
    auto steps_option = refusal([&] { check_stability_request(steps, stability_sources(true)); });
    CHECK(steps_option.first == "--steps 0, expected 1 to 2000");
    CHECK(steps_option.second == ExitCode::usage);
    auto grid = at_k;
    grid.grid = 401;
    CHECK(refusal([&] { check_stability_request(grid, stability_sources(false)); }).first ==
          "grid = 401, expected 2 to 400");
    auto path = at_k;
    path.path_points = 1;
    CHECK(refusal([&] { check_stability_request(path, stability_sources(true)); }).first ==
          "--path 1, expected 2 to 100000");
    path.path_points = 10;
    CHECK(stability_mode(path) == StabilityMode::path);
    path.wavevector = std::vector<double>{1, 0, 0};
    CHECK(refusal([&] { check_stability_request(path, stability_sources(false)); }).first ==
          "wavevector and path: give one of them");
    StabilityRequest range;
    range.k_min = 0.8;
    CHECK(refusal([&] { check_stability_request(range, stability_sources(false)); }).first ==
          "kmin and kmax go together, without k, wavevector or path");
    range.k_max = 1.2;
    CHECK(stability_mode(range) == StabilityMode::over_k);
    CHECK_NOTHROW(check_stability_request(range, stability_sources(true)));
    range.wavevector = std::vector<double>{1, 0, 0};
    auto together = refusal([&] { check_stability_request(range, stability_sources(true)); });
    CHECK(together.first == "--kmin and --kmax go together, without --k, --wavevector or --path");
    CHECK(together.second == ExitCode::usage);
    auto no_k = refusal([&] { check_stability_request(StabilityRequest{}, stability_sources(false)); });
    CHECK(no_k.first == "k: expected a number (or kmin and kmax)");
    CHECK(no_k.second == ExitCode::input);
}
