// Blends, kernel design and expression kernels, each against an independent check.
#include "analysis/design.hpp"
#include "analysis/roots.hpp"
#include "helpers.hpp"
#include "kernels/kernel_check.hpp"
#include "support/error.hpp"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace sphkern;
using sphkern::test::shipped_kernel;
using sphkern::test::shipped_kernels;

namespace {

std::string example(const std::string& name)
{
    return std::string(SPHKERN_SOURCE_DIR) + "/share/examples/expression-kernels/" + name + ".json";
}

DesignProblem problem_on(const Lattice& lattice, const std::string& parameter, double min, double max)
{
    DesignProblem problem;
    problem.lattice = &lattice;
    problem.a_p = lattice.volume_coefficient("voronoi");
    problem.gravity = lattice.gravity;
    problem.parameter = parameter;
    problem.parameter_min = min;
    problem.parameter_max = max;
    return problem;
}

} // namespace

TEST_CASE("a blend's errors are linear in alpha and its kernel is the weighted sum of the parts")
{
    auto lattice = load_lattice("triangular");
    Kernel a = shipped_kernel("liu_quartic"), b = shipped_kernel("morris_quintic");
    auto blend_definition = shipped_kernels().find("liu_quartic+morris_quintic");
    CHECK(blend_definition->support == 3.0);
    for (double alpha : {-0.5, 0.3, 1.7}) {
        Kernel blend(blend_definition, {{"alpha", alpha}});
        // The one-formula Liu kernel is cut at its own R = 2 inside the blend.
        CHECK(blend.w(2.5, 2, 1.0) == doctest::Approx(alpha * b.w(2.5, 2, 1.0)).epsilon(1e-14));
        CHECK(blend.w(0.7, 2, 1.0) == doctest::Approx((1 - alpha) * a.w(0.7, 2, 1.0) + alpha * b.w(0.7, 2, 1.0)).epsilon(1e-14));
        for (double k : {0.8, 1.05, 1.2}) {
            auto ea = HydrostaticErrors(a, lattice, 0, 0.866, lattice.gravity, 1.25).at(k);
            auto eb = HydrostaticErrors(b, lattice, 0, 0.866, lattice.gravity, 1.25).at(k);
            auto e = HydrostaticErrors(blend, lattice, 0, 0.866, lattice.gravity, 1.25).at(k);
            CHECK(e.eps_rho == doctest::Approx((1 - alpha) * ea.eps_rho + alpha * eb.eps_rho).epsilon(1e-12));
            CHECK(e.eps_gradp == doctest::Approx((1 - alpha) * ea.eps_gradp + alpha * eb.eps_gradp).epsilon(1e-12));
        }
    }
    // A 1D-only expression kernel and the 2D-only composite kernel share no dimension.
    auto one_d = std::filesystem::temp_directory_path() / "sphkern-test-one-d.json";
    std::ofstream(one_d) << R"({"name": "one_d", "support": 1, "dimensions": [1], "w": "q < 1 ? 1 - q : 0"})";
    CHECK_THROWS_WITH_AS(shipped_kernels().find("composite+" + one_d.string()), doctest::Contains("share no dimension"),
                         Error);
    std::filesystem::remove(one_d);
}

TEST_CASE("design: blends whose two errors vanish at one k, triangular and fcc, checked by brute force")
{
    for (const char* lattice_name : {"triangular", "fcc"}) {
        auto lattice = load_lattice(lattice_name);
        Kernel blend(shipped_kernels().find("cubic_bspline+desbrun_spiky"));
        auto problem = problem_on(lattice, "alpha", -1, 2);
        auto result = design_kernel(blend, problem);
        CAPTURE(lattice_name);
        REQUIRE(!result.solutions.empty());
        for (const auto& s : result.solutions) {
            CHECK(s.method == "blend");
            // Independently: the brute-force lattice sum of the designed kernel.
            Kernel designed(blend.shared_definition(), {{"alpha", s.parameter}});
            auto brute = test::brute_force_errors(designed, lattice, s.k, problem.a_p, lattice.gravity);
            CHECK(std::abs(brute.eps_rho) < 1e-9);
            CHECK(std::abs(brute.eps_gradp) < 1e-9);
            CHECK(std::isfinite(s.jacobian_condition));
        }
    }
}

TEST_CASE("design: the wendland_c2_shape family (not a blend) by bracketing and Newton")
{
    for (const char* lattice_name : {"triangular", "fcc"}) {
        auto lattice = load_lattice(lattice_name);
        Kernel family = shipped_kernel("wendland_c2_shape");
        auto problem = problem_on(lattice, "beta", -1, 10);
        auto result = design_kernel(family, problem);
        CAPTURE(lattice_name);
        REQUIRE(!result.solutions.empty());
        for (const auto& s : result.solutions) {
            CHECK(s.method == "newton");
            Kernel designed(family.shared_definition(), {{"beta", s.parameter}});
            auto brute = test::brute_force_errors(designed, lattice, s.k, problem.a_p, lattice.gravity);
            CHECK(std::abs(brute.eps_rho) < 1e-9);
            CHECK(std::abs(brute.eps_gradp) < 1e-9);
        }
    }
    // A range without a solution says so.
    auto lattice = load_lattice("triangular");
    auto none = problem_on(lattice, "beta", 5, 10);
    auto result = design_kernel(shipped_kernel("wendland_c2_shape"), none);
    CHECK(result.solutions.empty());
    CHECK(result.note.find("no (k, beta)") != std::string::npos);
    none.parameter = "gamma";
    CHECK_THROWS_WITH_AS(design_kernel(shipped_kernel("wendland_c2_shape"), none), doctest::Contains("no parameter"), Error);
}

TEST_CASE("an expression kernel matches the cubic_bspline plugin to 1e-12 in both errors")
{
    Kernel expression(shipped_kernels().find(example("cubic_bspline_expression")));
    Kernel plugin = shipped_kernel("cubic_bspline");
    for (const char* lattice_name : {"triangular", "fcc", "bcc"}) {
        auto lattice = load_lattice(lattice_name);
        double a_p = lattice.volume_coefficient("voronoi");
        HydrostaticErrors ex(expression, lattice, 0, a_p, lattice.gravity, 1.25), pl(plugin, lattice, 0, a_p, lattice.gravity, 1.25);
        for (int i = 0; i <= 50; ++i) {
            double k = 0.75 + 0.5 * i / 50;
            CHECK(std::abs(ex.at(k).eps_rho - pl.at(k).eps_rho) < 1e-12);
            CHECK(std::abs(ex.at(k).eps_gradp - pl.at(k).eps_gradp) < 1e-12);
        }
    }
    // Like the plugin: every check passes but the spectrum, negative in 2D and 3D for the B-spline.
    auto result = check_kernel(expression);
    CHECK(result["verdict"] == "warn");
    for (const auto& c : result["checks"])
        CHECK((c["status"] == "ok" || (c["check"] == "fourier" && c["dimension"] != 1)));
    // Without a "dw" expression the derivative is numerical, and check says so.
    Kernel power(shipped_kernels().find(example("wendland_c2_power")));
    auto checked = check_kernel(power);
    CHECK(checked["verdict"] == "ok");
    bool stated = false;
    for (const auto& c : checked["checks"]) stated |= c["check"] == "derivative" && c["detail"].get<std::string>().find("central difference") != std::string::npos;
    CHECK(stated);
    // Its normalisation, by quadrature, agrees with the closed form for p = 4 (Wendland C2 in 2D: 7 / (4 pi)).
    CHECK(power.w(0, 2, 1.0) == doctest::Approx(7 / (4 * M_PI)).epsilon(1e-12));
}
