#include "analysis/code_profiles.hpp"

#include "analysis/swift_gamma.hpp"
#include "support/error.hpp"

#include <boost/math/tools/toms748_solve.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace sphkern {

const std::vector<CodeProfile>& code_profiles()
{
    static const std::vector<CodeProfile> all{
        {"swift", "eta", true,
         {"cubic_bspline", "quartic_bspline", "morris_quintic", "wendland_c2", "wendland_c4", "wendland_c6"},
         "SWIFT's hydro documentation: h = eta (m / rho)^(1/D) solved with the SPH density, H = gamma h (Dehnen & Aly 2012)"},
        {"phantom", "hfact", true,
         {"cubic_bspline", "quartic_bspline", "morris_quintic", "wendland_c2", "wendland_c4", "wendland_c6"},
         "Price et al. 2018 (Phantom, PASA 35, e031): rho = m (hfact / h)^D with the SPH density, support radkern h"},
        {"gadget2", "nngb", true, {"cubic_bspline"},
         "Springel 2005 (GADGET-2, MNRAS 364, 1105): (4 pi / 3) H^3 rho = N_sph m, H the support radius"},
        {"gadget4", "nngb", true, {"cubic_bspline", "wendland_c2", "wendland_c4", "wendland_c6"},
         "Springel et al. 2021 (GADGET-4, MNRAS 506, 2871): DesNumNgb, the weighted neighbour number (4 pi / 3) H^3 rho / m"},
        {"pysph", "hdx", false, {"cubic_bspline", "wendland_c2", "wendland_c4", "wendland_c6", "morris_quintic", "super_gaussian"},
         "PySPH's examples: h = hdx dx with dx the particle spacing, support radius_scale h; its equations take "
         "W and its gradient at HIJ = (h_i + h_j) / 2 (pysph/sph/equation.py, precomputed_symbols)",
         true},
        {"dualsphysics", "coefh", false, {"cubic_bspline", "wendland_c2"},
         "DualSPHysics' user guide: h = coefh sqrt(3 dp^2) (sqrt(2 dp^2) in 2D), support 2h"},
        {"splishsplash", "particle_radius", false, {"cubic_bspline", "wendland_c2", "muller_poly6", "desbrun_spiky"},
         "SPlisHSPlasH's FluidModel: support radius 4 r for the particle radius r, particle volume 0.8 (2 r)^D "
         "(its kernels: cubic spline, Wendland quintic C2, poly6, spiky)",
         false, true}};
    return all;
}

const std::vector<const CodeProfile*>& study_codes()
{
    static const std::vector<const CodeProfile*> codes = [] {
        std::vector<const CodeProfile*> out;
        for (const auto& p : code_profiles())
            if (!p.sets_volume) out.push_back(&p);
        return out;
    }();
    return codes;
}

const CodeProfile& code_profile(const std::string& name, const ValueSource& source)
{
    std::vector<std::string> names;
    for (const auto& p : code_profiles()) {
        if (p.name == name) return p;
        names.push_back(p.name);
    }
    source.fail(fmt::format("\"{}\" is unknown, expected one of {}{}", name, fmt::join(names, ", "), did_you_mean(name, names)));
}

bool code_ships(const CodeProfile& profile, const Kernel& kernel)
{
    return std::find(profile.kernels.begin(), profile.kernels.end(), kernel.name()) != profile.kernels.end();
}

void require_code_kernel(const CodeProfile& profile, const Kernel& kernel)
{
    if (!code_ships(profile, kernel))
        fail_input(fmt::format("{}: {} does not ship it; its kernels are {}", kernel.name(), profile.name,
                               fmt::join(profile.kernels, ", ")));
}

double code_volume(const CodeProfile& p, int dim, double value)
{
    if (!p.sets_volume) throw std::logic_error(p.name + " does not fix the volume");
    return 0.8 * std::pow(2 * value, dim);
}

void require_lattice_volume(const CodeProfile& p, const std::string& what)
{
    if (p.sets_volume)
        fail_input(fmt::format("{}: its particle radius fixes the particle volume too (0.8 (2 r)^D), which {} cannot "
                               "take: expected eps or surface, which take the code's volume",
                               p.name, what));
}

double code_support_per_h(const CodeProfile& p, const Kernel& kernel, int dim)
{
    if (p.name == "swift") return swift_gamma(kernel, dim);
    if (p.name == "splishsplash") return 4; // its particle radius as h
    if (p.name == "gadget2" || p.name == "gadget4") return 1;
    if (p.name == "dualsphysics") return 2;
    return kernel.support(); // phantom's radkern, pysph's radius_scale
}

double code_parameter(const CodeProfile& p, const Kernel& kernel, int dim, double a_p, double k, double eps_rho)
{
    const double support = kernel.support() * k; // H / d
    const double rest_spacing = std::pow(a_p, 1.0 / dim);
    // (m / rho)^(1/D) in units of d: the code's own density where it solves for h.
    const double spacing = p.from_sph_density ? std::pow(a_p / (1 + eps_rho), 1.0 / dim) : rest_spacing;
    if (p.name == "swift") return support / swift_gamma(kernel, dim) / spacing;
    if (p.name == "phantom") return k / spacing;
    if (p.name == "gadget2" || p.name == "gadget4") {
        const double ball = dim == 3 ? 4 * std::numbers::pi / 3 : std::numbers::pi;
        return ball * std::pow(support, dim) / std::pow(spacing, dim);
    }
    if (p.name == "pysph") return k / spacing;
    if (p.name == "splishsplash") return support / 4;
    return support / (2 * std::sqrt(double(dim)) * spacing); // dualsphysics
}

double k_of_code_parameter(const CodeProfile& p, const Kernel& kernel, int dim, double a_p, double value,
                           double k_max, const std::function<double(double)>& eps_rho, const ValueSource& source)
{
    // At rest spacing the parameter is a power of k: its k is the start of the search.
    const double power = p.name == "gadget2" || p.name == "gadget4" ? dim : 1;
    const double at_one = code_parameter(p, kernel, dim, a_p, 1, 0);
    const double guess = std::pow(value / at_one, 1 / power);
    if (!p.from_sph_density) return guess;
    // With the SPH density it grows with k (each neighbour's W(r / H) does) and is flat where no
    // neighbour is inside the support: bracket the value, then solve.
    auto f = [&](double k) { return code_parameter(p, kernel, dim, a_p, k, eps_rho(k)) - value; };
    double lo = std::min(guess, k_max), hi = lo;
    while (f(lo) > 0 && lo > 1e-3) lo /= 1.25;
    while (f(hi) < 0 && hi < k_max) hi = std::min(k_max, hi * 1.25);
    if (f(lo) > 0)
        source.fail(fmt::format("{:g}: expected more than {:.6g}, the {} of a particle with no neighbour inside its support",
                                value, f(lo) + value, p.parameter));
    if (f(hi) < 0)
        source.fail(fmt::format("{:g}: expected at most {:.6g}, the {} at k = {:g}", value, f(hi) + value, p.parameter, hi));
    std::uintmax_t iterations = 200;
    const auto [a, b] = boost::math::tools::toms748_solve(
        f, lo, hi, [](double x, double y) { return std::abs(x - y) <= 1e-12 * std::max(1.0, std::abs(x)); }, iterations);
    return 0.5 * (a + b);
}

} // namespace sphkern
