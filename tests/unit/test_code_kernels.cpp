// Each code's kernels as the code's source writes them, against the sphkern kernel that the
// code's profile (core/codes/<code>/) maps the code's name to, at many q, in every dimension in
// which the profile says the code has it. Every formula is written as W H^D at x = r / H, H the
// support radius, with the file and routine it is read from. PySPH's are checked against PySPH's
// own classes (tests/python/test_code_kernels.py).
#include "codes/code_table.hpp"
#include "helpers.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <string>

using namespace sphkern;
using namespace sphkern::test;

namespace {

constexpr double pi = std::numbers::pi;

double pos(double v) { return v > 0 ? v : 0; }
double cube(double v) { return v * v * v; }

// The B-splines M4, M5, M6 in x = r / H, unnormalised.
double m4(double x) { return x < 0.5 ? 3 * cube(x) - 3 * x * x + 0.5 : cube(1 - x); }
double m5(double x) { return std::pow(pos(1 - x), 4) - 5 * std::pow(pos(0.6 - x), 4) + 10 * std::pow(pos(0.2 - x), 4); }
double m6(double x)
{
    return std::pow(pos(1 - x), 5) - 6 * std::pow(pos(2.0 / 3 - x), 5) + 15 * std::pow(pos(1.0 / 3 - x), 5);
}
// Wendland's functions of Dehnen & Aly (2012) for 2D and 3D, in x = r / H.
double c2(double x) { return std::pow(1 - x, 4) * (1 + 4 * x); }
double c4(double x) { return std::pow(1 - x, 6) * (1 + 6 * x + 35.0 / 3 * x * x); }
double c6(double x) { return std::pow(1 - x, 8) * (1 + 8 * x + 25 * x * x + 32 * cube(x)); }

using Form = std::function<double(double x, int dim)>; // W H^D at x = r / H
// A normalisation per dimension (index D - 1) times a shape.
Form scaled(std::array<double, 3> norm, double (*shape)(double))
{
    return [norm, shape](double x, int dim) { return norm[dim - 1] * shape(x); };
}

// A form given in the code's own q = r / h with H = ratio h: W h^D = f(q), so W H^D = ratio^D f(q).
Form in_h(double ratio, std::array<double, 3> norm, std::function<double(double)> f)
{
    return [=](double x, int dim) { return std::pow(ratio, dim) * norm[dim - 1] * f(x * ratio); };
}

std::map<std::pair<std::string, std::string>, Form> written()
{
    // GADGET-2 allvars.h (KERNEL_COEFF_1..6) and density.c; GADGET-4 src/sph/kernel.h (NORM,
    // kernel_main): the cubic spline as 1 + 6 (u - 1) u^2 below u = 1/2, 2 (1 - u)^3 above.
    const Form gadget_cubic = [](double u, int dim) {
        const double norm = dim == 3 ? 8 / pi : dim == 2 ? 40 / (7 * pi) : 4.0 / 3;
        return norm * (u < 0.5 ? 1 + 6 * (u - 1) * u * u : 2 * cube(1 - u));
    };
    // Phantom's kernel_*.f90 (cnormk, get_kernel), q = r / h, H = radkern h.
    const auto phantom = [](double radkern, double cnormk, std::function<double(double)> f) {
        return in_h(radkern, {0, 0, cnormk}, std::move(f));
    };
    const auto phantom_cubic = [](double q) { return q < 1 ? 0.75 * cube(q) - 1.5 * q * q + 1 : 0.25 * cube(2 - q); };
    return {
        // SWIFT src/kernel_hydro.h: kernel_constant per dimension times its polynomial in x = u / kernel_gamma.
        {{"swift", "Cubic spline (M4)"}, scaled({8.0 / 3, 80 / (7 * pi), 16 / pi}, m4)},
        {{"swift", "Quartic spline (M5)"}, scaled({3125.0 / 768, 46875 / (2398 * pi), 15625 / (512 * pi)}, m5)},
        {{"swift", "Quintic spline (M6)"}, scaled({243.0 / 40, 15309 / (478 * pi), 2187 / (40 * pi)}, m6)},
        {{"swift", "Wendland C2"}, scaled({NAN, 7 / pi, 21 / (2 * pi)}, c2)},
        {{"swift", "Wendland C4"}, scaled({NAN, 9 / pi, 495 / (32 * pi)}, c4)},
        {{"swift", "Wendland C6"}, scaled({NAN, 78 / (7 * pi), 1365 / (64 * pi)}, c6)},
        {{"phantom", "cubic"}, phantom(2, 1 / pi, phantom_cubic)},
        {{"phantom", "quartic"},
         phantom(2.5, 0.05 / pi,
                 [](double q) {
                     return std::pow(pos(2.5 - q), 4) - 5 * std::pow(pos(1.5 - q), 4) + 10 * std::pow(pos(0.5 - q), 4);
                 })},
        {{"phantom", "quintic"},
         phantom(3, 1 / (120 * pi),
                 [](double q) {
                     return std::pow(pos(3 - q), 5) - 6 * std::pow(pos(2 - q), 5) + 15 * std::pow(pos(1 - q), 5);
                 })},
        {{"phantom", "WendlandC2"},
         phantom(2, 21 / (16 * pi), [](double q) { return std::pow(1 - q / 2, 4) * (2 * q + 1); })},
        {{"phantom", "WendlandC4"},
         phantom(2, 495 / (256 * pi), [](double q) { return std::pow(1 - q / 2, 6) * (35 * q * q / 12 + 3 * q + 1); })},
        {{"phantom", "WendlandC6"},
         phantom(2, 1365 / (512 * pi),
                 [](double q) { return std::pow(q / 2 - 1, 8) * (4 * cube(q) + 6.25 * q * q + 4 * q + 1); })},
        {{"gadget2", "cubic spline"}, gadget_cubic},
        {{"gadget4", "CUBIC_SPLINE_KERNEL"}, gadget_cubic},
        {{"gadget4", "WENDLAND_C2_KERNEL"}, scaled({NAN, 7 / pi, 21 / (2 * pi)}, c2)},
        {{"gadget4", "WENDLAND_C4_KERNEL"}, scaled({NAN, 9 / pi, 495 / (32 * pi)}, c4)},
        {{"gadget4", "WENDLAND_C6_KERNEL"}, scaled({NAN, 78 / (7 * pi), 1365 / (64 * pi)}, c6)},
        // DualSPHysics src/source/FunSphKernel.h (GetKernelCubic_Wab with GetKernelCubic_Ctes, 10/(7 pi) in 2D
        // and 1/pi in 3D; GetKernelWendland_Wab, awen (2q + 1)(1 - q/2)^4), q = r / h, H = 2 h. Its awen is
        // printed to the digits 0.557 (2D) and 0.41778 (3D): 7 / (4 pi) and 21 / (16 pi) rounded.
        {{"dualsphysics", "Cubic"},
         in_h(2, {NAN, 10 / (7 * pi), 1 / pi},
              [](double q) { return q < 1 ? 1 - 1.5 * q * q + 0.75 * cube(q) : 0.25 * cube(2 - q); })},
        {{"dualsphysics", "Wendland"},
         in_h(2, {NAN, 0.557, 0.41778}, [](double q) { return (2 * q + 1) * std::pow(1 - q / 2, 4); })},
        // SPlisHSPlasH/SPHKernels.h, its h the support radius: CubicKernel(2D) m_k 8 / pi (40 / (7 pi)) with
        // 6 q^3 - 6 q^2 + 1 and 2 (1 - q)^3; WendlandQuinticC2Kernel(2D) 21 / (2 pi) (7 / pi); Poly6Kernel
        // 315 / (64 pi h^9) (h^2 - r^2)^3; SpikyKernel 15 / (pi h^6) (h - r)^3.
        {{"splishsplash", "CubicKernel"},
         [](double q, int dim) {
             return (dim == 3 ? 8 / pi : 40 / (7 * pi)) * (q <= 0.5 ? 6 * cube(q) - 6 * q * q + 1 : 2 * cube(1 - q));
         }},
        {{"splishsplash", "WendlandQuinticC2Kernel"}, scaled({NAN, 7 / pi, 21 / (2 * pi)}, c2)},
        {{"splishsplash", "Poly6Kernel"}, [](double x, int) { return 315 / (64 * pi) * cube(1 - x * x); }},
        {{"splishsplash", "SpikyKernel"}, [](double x, int) { return 15 / pi * cube(1 - x); }},
    };
}

// The digits the code prints its constant to, where it rounds one (DualSPHysics' awen).
double printed_digits(const std::string& code, const std::string& name)
{
    return code == "dualsphysics" && name == "Wendland" ? 1e-4 : 1e-12;
}

} // namespace

TEST_CASE("every code's kernel, in every dimension the code has it, is the sphkern kernel its profile names")
{
    const auto forms = written();
    int compared = 0;
    for (const auto& code : code_profiles()) {
        if (code.name == "pysph") continue; // against PySPH's own classes, in Python
        for (const auto& k : code.kernels) {
            CAPTURE(code.name);
            CAPTURE(k.code_name);
            const auto form = forms.find({code.name, k.code_name});
            REQUIRE_MESSAGE(form != forms.end(), "no formula written out for this code's kernel");
            const Kernel kernel = shipped_kernel(k.kernel);
            const double R = kernel.support();
            for (int dim : k.dimensions) {
                CAPTURE(dim);
                REQUIRE(kernel.supports(dim));
                // W H^D = w(q) R^D at q = x R, sphkern's W = w(q) / h^D with H = R h.
                const double scale = form->second(0, dim) / (kernel.w(0, dim, 1) * std::pow(R, dim));
                CHECK(std::abs(scale - 1) <= printed_digits(code.name, k.code_name));
                for (int i = 1; i < 200; ++i) {
                    const double x = i / 200.0;
                    CHECK(form->second(x, dim) == doctest::Approx(scale * kernel.w(x * R, dim, 1) * std::pow(R, dim))
                                                      .epsilon(1e-12)
                                                      .scale(form->second(0, dim)));
                }
                ++compared;
            }
        }
    }
    CHECK(compared >= 30);
}

TEST_CASE("a code refuses a dimension it does not run and a kernel it does not have there, naming what it has")
{
    const auto source = ValueSource::option("--code");
    const Kernel cubic = shipped_kernel("cubic_bspline"), poly6 = shipped_kernel("muller_poly6");
    // Phantom is 3D only (config.F90); SPlisHSPlasH's 2D simulation has the cubic and Wendland C2 only
    // (Simulation.cpp).
    CHECK_FALSE(code_ships(code_profile("phantom", source), cubic, 2));
    CHECK(code_ships(code_profile("phantom", source), cubic, 3));
    CHECK_FALSE(code_ships(code_profile("splishsplash", source), poly6, 2));
    CHECK(code_ships(code_profile("splishsplash", source), poly6, 3));
    try {
        require_code_kernel(code_profile("phantom", source), cubic, 2);
        FAIL("phantom in 2D was accepted");
    } catch (const Error& e) {
        CHECK(e.code() == ExitCode::usage);
        CHECK(std::string(e.what()) == "cubic_bspline: phantom runs in 3D only, not in 2D");
    }
    try {
        require_code_kernel(code_profile("splishsplash", source), poly6, 2);
        FAIL("poly6 in SPlisHSPlasH's 2D was accepted");
    } catch (const Error& e) {
        CHECK(e.code() == ExitCode::usage);
        CHECK(std::string(e.what()) ==
              "muller_poly6: splishsplash has it in 3D only; its kernels in 2D are cubic_bspline, wendland_c2");
    }
    // PySPH takes a kernel it does not ship (its schemes take any kernel object).
    CHECK_NOTHROW(require_code_kernel(code_profile("pysph", source), poly6, 2));
    // The 2D SuperGaussian of PySPH is not the paper's.
    CHECK_FALSE(code_ships(code_profile("pysph", source), shipped_kernel("super_gaussian"), 2));
    CHECK(code_ships(code_profile("pysph", source), shipped_kernel("pysph_super_gaussian"), 2));
    CHECK(code_ships(code_profile("pysph", source), shipped_kernel("super_gaussian"), 3));
}
