// ABI 2 and its extensions, the second derivative and the Fourier transform of a kernel,
// and the check-up's new failures, each against an independent value.
#include "analysis/hydrostatic_errors.hpp"
#include "helpers.hpp"
#include "kernels/kernel_check.hpp"
#include "kernels/kernel_plugin.hpp"
#include "kernels/kernel_spectrum.hpp"
#include "support/error.hpp"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <cmath>

using namespace sphkern;
using namespace sphkern::test;

namespace {

constexpr double pi = 3.14159265358979323846;

std::string fixture(const std::string& name) { return std::string(SPHKERN_BROKEN_PLUGIN_DIR) + "/" + name + ".so"; }

// The cubic B-spline's pieces and their derivatives, written out (sigma_D aside).
double spline_d2(double q) { return q <= 1 ? -2 + 3 * q : q <= 2 ? 2 - q : 0; }

// Wendland C2 in 3D: 21/(16 pi) (1 - q/2)^4 (2q + 1); W'' by hand.
double wendland_c2_3d_d2(double q)
{
    const double s = 21 / (16 * pi), t = 1 - q / 2;
    // W = s t^4 (2q+1): W' = s (-2 t^3 (2q+1) + 2 t^4) = -5 s q t^3; W'' = -5 s (t^3 - 1.5 q t^2)
    return q <= 2 ? -5 * s * (t * t * t - 1.5 * q * t * t) : 0;
}

std::map<std::string, std::string> statuses(const nlohmann::json& result, int dim)
{
    std::map<std::string, std::string> s;
    for (const auto& c : result["checks"])
        if (c["dimension"] == dim) s[c["check"]] = c["status"];
    return s;
}

} // namespace

TEST_CASE("a plugin built against the frozen ABI 1 header loads and agrees with the ABI 2 cubic_bspline")
{
    Kernel old(load_kernel_plugin(fixture("abi1_cubic"))), now = shipped_kernel("cubic_bspline");
    CHECK(old.definition().abi == "1.0");
    CHECK(now.definition().abi == "2.1");
    for (const char* name : {"triangular", "fcc"}) {
        auto lattice = load_lattice(name);
        const double a_p = lattice.volume_coefficient("voronoi");
        HydrostaticErrors a(old, lattice, 0, a_p, lattice.gravity, 1.3), b(now, lattice, 0, a_p, lattice.gravity, 1.3);
        for (double k : {0.8, 1.0, 1.2}) {
            CHECK(a.at(k).eps_rho == b.at(k).eps_rho);
            CHECK(a.at(k).eps_gradp == b.at(k).eps_gradp);
        }
    }
}

TEST_CASE("the loader refuses unknown flags and names a missing extern \"C\"")
{
    auto message = [](const std::string& name) {
        try {
            load_kernel_plugin(fixture(name));
        } catch (const Error& e) {
            CHECK(e.code() == ExitCode::plugin);
            return std::string(e.what());
        }
        FAIL("accepted " << name);
        return std::string();
    };
    CHECK(message("unknown_flags").find("flags 0x80 has bits this sphkern does not define") != std::string::npos);
    CHECK(message("cxx_without_extern_c").find("declare the entry function extern \"C\"") != std::string::npos);
    CHECK(message("wrong_abi").find("reads versions 1 and 2") != std::string::npos);
}

TEST_CASE("the numerical second derivative matches W'' written by hand to 1e-8, on breakpoints too")
{
    Kernel spline = shipped_kernel("cubic_bspline"), wendland = shipped_kernel("wendland_c2");
    CHECK_FALSE(spline.provides_second_derivative());
    const double sigma3 = 3 / (2 * pi);
    double worst = 0;
    for (int i = 0; i <= 400; ++i) {
        const double q = 2.0 * i / 400; // hits q = 1 (breakpoint) and q = 2 (R) exactly
        // On a breakpoint the inner side counts.
        const double expected_spline = sigma3 * (q == 1.0 ? 1.0 : spline_d2(q));
        worst = std::max(worst, std::abs(spline.d2w(q, 3, 1.0) - expected_spline) / sigma3);
        worst = std::max(worst, std::abs(wendland.d2w(q, 3, 1.0) - wendland_c2_3d_d2(q)) / (5 * 21 / (16 * pi)));
    }
    CHECK(worst < 1e-8);
    MESSAGE("largest relative error of the numerical W'': " << worst);
}

TEST_CASE("a provided second derivative and Fourier transform are used and pass the check")
{
    Kernel k(load_kernel_plugin(fixture("with_extensions")));
    CHECK(k.provides_second_derivative());
    CHECK(k.provides_fourier_transform());
    CHECK(k.d2w(0.5, 1, 1.0) == doctest::Approx(-0.5).epsilon(1e-15));
    auto result = check_kernel(k);
    CHECK(result["verdict"] == "ok");
    CHECK(result["second_derivative"] == "plugin");
    CHECK(result["fourier"]["1"]["source"] == "plugin");
    auto s = statuses(result, 1);
    CHECK(s["second_derivative"] == "ok");
    CHECK(s["fourier_provided"] == "ok");
}

TEST_CASE("the Fourier transform by quadrature matches the B-spline's closed forms in 1D and 3D")
{
    Kernel spline = shipped_kernel("cubic_bspline");
    // 1D: (sin(x/2)/(x/2))^4. 3D: for a radial f, F3(x) = -(2 pi / x) dF1/dx with F1 the
    // 1D transform of the same profile, here sigma3/sigma1 (sin(x/2)/(x/2))^4.
    auto s = [](double x) { return std::sin(x / 2) / (x / 2); };
    auto ds = [](double x) { return std::cos(x / 2) / x - 2 * std::sin(x / 2) / (x * x); };
    double worst1 = 0, worst3 = 0;
    for (int i = 1; i <= 200; ++i) {
        const double x = 0.25 * i;
        worst1 = std::max(worst1, std::abs(spline.fourier(x, 1, 1.0) - std::pow(s(x), 4)));
        const double f3 = -(2 * pi / x) * (3 / (2 * pi)) * 4 * std::pow(s(x), 3) * ds(x);
        worst3 = std::max(worst3, std::abs(spline.fourier(x, 3, 1.0) - f3));
    }
    CHECK(worst1 < 1e-12);
    CHECK(worst3 < 1e-12);
    CHECK(spline.fourier(0, 2, 1.0) == doctest::Approx(1).epsilon(1e-12));
    // The 3D spectrum first vanishes where sin(x/2) does: x = 2 pi, a triple zero (s^3), so
    // rounding of 1e-16 in the values moves it by up to (1e-16 / |F3 third derivative|)^(1/3) ~ 1e-5.
    auto summary = spectrum_summary(spline, 3, 1.0);
    REQUIRE(summary.first_zero);
    CHECK(*summary.first_zero == doctest::Approx(2 * pi).epsilon(1e-4));
    CHECK(summary.minimum < 0);
    // Wendland C2 is positive definite in 3D (Wendland 1995): no negative value.
    CHECK(spectrum_summary(shipped_kernel("wendland_c2"), 3, 1.0).minimum > -1e-12);
}

TEST_CASE(
    "check fails a wrong derivative and warns of a hidden jump, an over-declared support and a missing breakpoint")
{
    auto checked = [](const std::string& name) { return check_kernel(Kernel(load_kernel_plugin(fixture(name)))); };
    auto wrong = checked("wrong_derivative");
    CHECK(wrong["verdict"] == "fail");
    auto s = statuses(wrong, 1);
    CHECK(s["derivative"] == "fail");
    CHECK(s["gradient_moment"] == "fail");
    CHECK(s["second_derivative"] == "fail");
    // A plugin's hint speaks of its C terms (an expression file's of its keys: test_design.cpp).
    bool named = false;
    for (const auto& c : wrong["checks"])
        named |= c["check"] == "derivative" &&
                 c.value("hint", std::string()).find("SPHKERN_KERNEL_SEPARATE_DERIVATIVE") != std::string::npos;
    CHECK(named);
    CHECK(statuses(checked("hidden_jump"), 1)["breakpoints"] == "warn");
    CHECK(statuses(checked("over_declared_support"), 1)["support"] == "warn");
    auto missing = checked("missing_breakpoint");
    CHECK(statuses(missing, 1)["breakpoints"] == "warn");
    bool located = false;
    for (const auto& c : missing["checks"])
        located |= c["check"] == "breakpoints" &&
                   c["detail"].get<std::string>().find("q = 0.4999") != std::string::npos && c.contains("hint");
    CHECK(located);
    // The shipped kernels have none of these faults.
    for (const char* name : {"cubic_bspline", "wendland_c6", "morris_quintic", "desbrun_spiky"}) {
        auto result = check_kernel(shipped_kernel(name));
        for (const auto& c : result["checks"])
            if (c["check"] == "breakpoints" || c["check"] == "support" || c["check"] == "gradient_moment")
                CHECK_MESSAGE(c["status"] == "ok", name << ": " << c.dump());
    }
}

TEST_CASE("the fused W and W' of every shipped plugin equal its scalar functions, and without the extension the "
          "batches give them")
{
    std::vector<double> q;
    for (int i = 0; i <= 400; ++i) q.push_back(1.5 * i / 400); // in units of R below
    int fused = 0;
    for (const auto& definition : shipped_kernels().plugins()) {
        if (definition->abi != "2.1") continue;
        CAPTURE(definition->name);
        const Kernel kernel(definition);
        std::vector<double> qs, w(q.size()), dw(q.size());
        for (double x : q) qs.push_back(x * kernel.support());
        for (int dim = 1; dim <= 3; ++dim) {
            if (!kernel.supports(dim)) continue;
            kernel.w_dw_batch(qs.data(), w.data(), dw.data(), qs.size(), dim, 1.2);
            for (std::size_t i = 0; i < qs.size(); ++i) {
                CHECK(w[i] == doctest::Approx(kernel.w(qs[i], dim, 1.2)).epsilon(1e-12).scale(1));
                CHECK(dw[i] == doctest::Approx(kernel.dw(qs[i], dim, 1.2)).epsilon(1e-12).scale(1));
            }
        }
        ++fused;
    }
    CHECK(fused >= 12); // every shipped plugin gives the extension
    // ABI 1 has no extension: the host's fallback calls the two batch functions.
    const Kernel old(load_kernel_plugin(fixture("abi1_cubic")));
    std::vector<double> w(q.size()), dw(q.size()), w_batch(q.size()), dw_batch(q.size());
    old.w_dw_batch(q.data(), w.data(), dw.data(), q.size(), 3, 1.0);
    old.w_batch(q.data(), w_batch.data(), q.size(), 3, 1.0);
    old.dw_batch(q.data(), dw_batch.data(), q.size(), 3, 1.0);
    CHECK(w == w_batch);
    CHECK(dw == dw_batch);
}

TEST_CASE("a fused W and W' that disagree with the scalar functions are refused by the probe")
{
    CHECK_THROWS_WITH_AS(load_kernel_plugin(fixture("fused_disagrees")),
                         doctest::Contains("the fused and scalar functions disagree at q = "), Error);
}
