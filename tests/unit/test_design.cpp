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
#include <map>
#include <set>
#include <string>

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
        CHECK(blend.w(0.7, 2, 1.0) ==
              doctest::Approx((1 - alpha) * a.w(0.7, 2, 1.0) + alpha * b.w(0.7, 2, 1.0)).epsilon(1e-14));
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
    CHECK_THROWS_WITH_AS(design_kernel(shipped_kernel("wendland_c2_shape"), none), doctest::Contains("no parameter"),
                         Error);
}

TEST_CASE("an expression kernel matches the cubic_bspline plugin to 1e-12 in both errors")
{
    Kernel expression(shipped_kernels().find(example("cubic_bspline_expression")));
    Kernel plugin = shipped_kernel("cubic_bspline");
    for (const char* lattice_name : {"triangular", "fcc", "bcc"}) {
        auto lattice = load_lattice(lattice_name);
        double a_p = lattice.volume_coefficient("voronoi");
        HydrostaticErrors ex(expression, lattice, 0, a_p, lattice.gravity, 1.25),
            pl(plugin, lattice, 0, a_p, lattice.gravity, 1.25);
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
    for (const auto& c : checked["checks"])
        stated |= c["check"] == "derivative" &&
                  c["detail"].get<std::string>().find("central difference") != std::string::npos;
    CHECK(stated);
    // Its normalisation, by quadrature, agrees with the closed form for p = 4 (Wendland C2 in 2D: 7 / (4 pi)).
    CHECK(power.w(0, 2, 1.0) == doctest::Approx(7 / (4 * M_PI)).epsilon(1e-12));
}

namespace {

// Wendland C4 with support R = 2 (q = r/h) as an expression file: `constant` times the shape
// in "w" and in "dw", and any further keys.
std::string wendland_c4_file(const std::string& name, const std::string& constant, const std::string& dimensions,
                             const std::string& extra = "", const std::string& dw_factor = "14/3")
{
    auto file = std::filesystem::temp_directory_path() / ("sphkern-test-" + name + ".json");
    std::ofstream(file) << R"({"name": ")" << name << R"(", "support": 2, "dimensions": )" << dimensions << ", "
                        << extra << R"("w": "q < 2 ? )" << constant
                        << R"( * (1 - q/2)^6 * (1 + 3*q + 35/12*q^2) : 0", )"
                        << R"("dw": "q < 2 ? -)" << constant << " * " << dw_factor
                        << R"( * q * (1 - q/2)^5 * (1 + 2.5*q) : 0"})";
    return file.string();
}

// The Wendland C4 constant for support R in D dimensions: 1 over the integral of the shape
// (1 - q/R)^6 (1 + 6 q/R + 35/3 (q/R)^2) over D-space, by composite Simpson (a polynomial of
// degree 12 at most: 4000 panels leave ~1e-14).
double wendland_c4_constant(int dim, double R)
{
    auto f = [&](double q) {
        const double s = q / R;
        return std::pow(1 - s, 6) * (1 + 6 * s + 35.0 / 3 * s * s) * std::pow(q, dim - 1);
    };
    const int n = 4000;
    double sum = f(0) + f(R);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4 : 2) * f(R * i / n);
    const double area = dim == 2 ? 2 * M_PI : 4 * M_PI;
    return 1 / (area * sum * R / n / 3);
}

nlohmann::json check_item(const nlohmann::json& result, int dim, const std::string& name)
{
    for (const auto& c : result["checks"])
        if (c["dimension"] == dim && c["check"] == name) return c;
    FAIL("no check " << name << " in " << dim << "D");
    return {};
}

// The number that follows `before` in `text`.
double number_after(const std::string& text, const std::string& before)
{
    const auto at = text.find(before);
    REQUIRE_MESSAGE(at != std::string::npos, text);
    return std::stod(text.substr(at + before.size()));
}

} // namespace

TEST_CASE("an expression kernel is used as written: check judges its constant and names the right one")
{
    // The closed forms 495/(32 pi R^3) and 9/(pi R^2), R = 2, confirmed by the quadrature above.
    const double c3 = 495 / (32 * M_PI * 8), c2 = 9 / (M_PI * 4);
    REQUIRE(wendland_c4_constant(3, 2) == doctest::Approx(c3).epsilon(1e-12));
    REQUIRE(wendland_c4_constant(2, 2) == doctest::Approx(c2).epsilon(1e-12));

    // The right constant: every check passes, and W is the formula as written.
    auto right_file = wendland_c4_file("c4_right", "495/(256*_pi)", "[3]");
    Kernel right(shipped_kernels().find(right_file));
    CHECK(right.w(0, 3, 1.0) == doctest::Approx(c3).epsilon(1e-14));
    auto result = check_kernel(right);
    CHECK(result["verdict"] == "ok");

    // The support-1 constant on the support-2 formula, 8 times too large in w and dw: the
    // normalisation fails (the gradient moment, consistent with it, does not), and the hint
    // gives the factor and the constant in the file's terms, not the plugin's.
    auto wrong_file = wendland_c4_file("c4_wrong", "495/(32*_pi)", "[3]");
    Kernel wrong(shipped_kernels().find(wrong_file));
    CHECK(wrong.w(0, 3, 1.0) == doctest::Approx(8 * c3).epsilon(1e-14));
    result = check_kernel(wrong);
    CHECK(result["verdict"] == "fail");
    CHECK(result["normalization"]["3"].get<double>() == doctest::Approx(8).epsilon(1e-12));
    CHECK(check_item(result, 3, "gradient_moment")["status"] == "ok");
    auto normalization = check_item(result, 3, "normalization");
    CHECK(normalization["status"] == "fail");
    const std::string hint = normalization["hint"];
    CAPTURE(hint);
    CHECK(hint.find("\"w\" in " + wrong_file) != std::string::npos);
    CHECK(number_after(hint, "multiply \"w\" and \"dw\" by ") == doctest::Approx(1.0 / 8).epsilon(1e-9));
    CHECK(number_after(hint, "W(0) = ") == doctest::Approx(c3).epsilon(1e-9));
    CHECK(hint.find("\"normalise\": true") != std::string::npos);
    CHECK(hint.find("divide the 3D constant") == std::string::npos);

    // "normalise": true asks sphkern to divide by the integral: the wrong constant no longer matters.
    auto normalised_file = wendland_c4_file("c4_normalised", "495/(32*_pi)", "[3]", R"("normalise": true, )");
    Kernel normalised(shipped_kernels().find(normalised_file));
    CHECK(normalised.w(0, 3, 1.0) == doctest::Approx(c3).epsilon(1e-12));
    CHECK(check_kernel(normalised)["verdict"] == "ok");
    // "normalise": false is the default, the formula as written.
    auto false_file = wendland_c4_file("c4_false", "495/(32*_pi)", "[3]", R"("normalise": false, )");
    Kernel as_written(shipped_kernels().find(false_file));
    CHECK(as_written.w(0, 3, 1.0) == doctest::Approx(8 * c3).epsilon(1e-14));

    // One formula has one constant: right in 3D, it is wrong in 2D, and the 2D hint gives the
    // 2D constant and says why one file cannot hold both.
    auto both_file = wendland_c4_file("c4_both", "495/(256*_pi)", "[2, 3]");
    result = check_kernel(Kernel(shipped_kernels().find(both_file)));
    CHECK(check_item(result, 3, "normalization")["status"] == "ok");
    const std::string hint2 = check_item(result, 2, "normalization")["hint"];
    CAPTURE(hint2);
    CHECK(number_after(hint2, "W(0) = ") == doctest::Approx(c2).epsilon(1e-9));
    CHECK(hint2.find("give 2D a file of its own") != std::string::npos);

    // A non-boolean "normalise" is refused, naming the file and the key.
    auto yes_file = wendland_c4_file("c4_yes", "495/(256*_pi)", "[3]", R"("normalise": "yes", )");
    auto [message, code] = test::refusal([&] { shipped_kernels().find(yes_file); });
    CHECK(message == yes_file + ": /normalise: expected true or false, got a string");
    CHECK(code == ExitCode::input);

    // A wrong "dw" (14/3 written 4): the derivative hints name "dw" and the file, no C macro.
    auto dw_file = wendland_c4_file("c4_dw", "495/(256*_pi)", "[3]", "", "4");
    result = check_kernel(Kernel(shipped_kernels().find(dw_file)));
    CHECK(result["verdict"] == "fail");
    for (const char* name : {"derivative", "gradient_moment"}) {
        auto item = check_item(result, 3, name);
        CAPTURE(item.dump());
        CHECK(item["status"] == "fail");
        const std::string text = item["hint"];
        CHECK(text.find("\"dw\" in " + dw_file) != std::string::npos);
        CHECK(text.find("SPHKERN_") == std::string::npos);
    }
    for (const auto& file : {right_file, wrong_file, normalised_file, false_file, both_file, yes_file, dw_file})
        std::filesystem::remove(file);
}

TEST_CASE("every hint check gives an expression kernel names the file and its keys, not the plugin's terms")
{
    const auto folder = std::filesystem::temp_directory_path();
    const std::map<std::string, std::string> kernels = {
        // Normalised over all space and cut at R = 3: the loss at R, and W not zero there.
        {"x_gauss", R"j("support": 3, "w": "exp(-q^2) / _pi^1.5", "dw": "-2*q*exp(-q^2) / _pi^1.5")j"},
        // A kink of dW/dr at q = 1, not declared.
        {"x_kink", R"j("support": 2, "normalise": true, "w": "q < 1 ? 1.5 - q : (q < 2 ? (2 - q)^2 / 2 : 0)",
                      "dw": "q < 1 ? -1 : (q < 2 ? q - 2 : 0)")j"},
        // Pieces that do not meet at the declared breakpoint.
        {"x_jump",
         R"j("support": 2, "normalise": true, "breakpoints": [1], "w": "q < 1 ? 1 : (q < 2 ? (2 - q) / 2 : 0)",
                      "dw": "q < 1 ? 0 : (q < 2 ? -0.5 : 0)")j"},
        // W ends at 2, the support says 3.
        {"x_wide",
         R"j("support": 3, "normalise": true, "w": "q < 2 ? (2 - q)^3 : 0", "dw": "q < 2 ? -3*(2 - q)^2 : 0")j"},
        // Not finite at k = 0.75.
        {"x_pole", R"j("support": 2, "normalise": true, "w": "(q < 2 ? (2 - q)^3 : 0) / (k - 0.75)",
                      "dw": "(q < 2 ? -3*(2 - q)^2 : 0) / (k - 0.75)")j"}};
    std::set<std::string> flagged;
    for (const auto& [name, keys] : kernels) {
        const auto file = (folder / ("sphkern-test-" + name + ".json")).string();
        std::ofstream(file) << R"({"name": ")" << name << R"(", "dimensions": [3], )" << keys << "}";
        auto result = check_kernel(Kernel(shipped_kernels().find(file)));
        std::filesystem::remove(file);
        for (const auto& c : result["checks"]) {
            if (c["status"] == "ok" || c["check"] == "fourier")
                continue; // the spectrum's hint is about W, not the file
            CAPTURE(c.dump());
            const std::string hint = c["hint"];
            CHECK(hint.find(file) != std::string::npos);
            CHECK(hint.find("SPHKERN_") == std::string::npos);
            CHECK(hint.find("declare") == std::string::npos);
            flagged.insert(c["check"].get<std::string>());
        }
    }
    CHECK(flagged == std::set<std::string>{"normalization", "continuity", "gradient_moment", "breakpoints", "support",
                                           "finiteness"});
}
