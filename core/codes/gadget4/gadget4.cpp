#include "codes/gadget4/gadget4.hpp"

#include "codes/neighbour_number.hpp"
#include "support/error.hpp"
#include "support/text/value_checks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace sphkern {

namespace {

// WENDLAND_BIAS_CORRECTION (Dehnen & Aly 2012, eqs. 18-19): src/sph/kernel.h, get_density_bias,
// subtracts eps100 (DesNumNgb / 100)^(-alpha) m W(0, H) from the density, with eps100 and alpha
// per kernel from get_bias_correction_parameters; src/sph/density.cc applies it after each
// density pass, before NumNgb = NORM_COEFF H^3 Density / Mass is compared with DesNumNgb, so
// the solve counts the corrected density. kernel.h stops the build for another kernel or for
// ONEDIMS and TWODIMS; DesNumNgb is an int (src/data/allvars.h).
double wendland_bias(const Kernel& kernel, int dimension, double nngb, const ValueSource& source)
{
    struct Parameters {
        const char* kernel;
        double eps100, alpha;
    };
    static constexpr Parameters table[] = {{"wendland_c2", 0.0294, 0.977},
                                           {"wendland_c4", 0.01342, 1.579},
                                           {"wendland_c6", 0.0116, 2.236}};
    const auto* p = std::find_if(std::begin(table), std::end(table),
                                 [&](const Parameters& e) { return kernel.name() == e.kernel; });
    if (p == std::end(table) || dimension != 3)
        throw Error(source.code, fmt::format("GADGET-4's WENDLAND_BIAS_CORRECTION is for its Wendland C2, C4 and C6 "
                                             "kernels in 3D only (src/sph/kernel.h), not {} in {}D",
                                             kernel.name(), dimension));
    if (nngb != std::floor(nngb))
        source.fail(
            fmt::format("{:g}: GADGET-4's DesNumNgb is an integer (src/data/allvars.h); expected a whole number",
                        nngb));
    return p->eps100 * std::pow(nngb / 100, -p->alpha);
}

} // namespace

CodeProfile gadget4_code()
{
    // 3D, 2D with TWODIMS and 1D with ONEDIMS (sph/kernel.h: NORM per dimension); the cubic spline
    // and the Wendland kernels, whose 1D forms are other functions than sphkern's (which has none in 1D).
    const std::vector<int> all{1, 2, 3}, dims{2, 3};
    CodeProfile p;
    p.name = "gadget4";
    p.title = "GADGET-4";
    p.parameter = "nngb";
    p.parameter_help = "the weighted neighbour number";
    p.source = "Springel et al. 2021 (GADGET-4, MNRAS 506, 2871): DesNumNgb, the weighted neighbour number "
               "(4 pi / 3) H^3 rho / m";
    p.from_sph_density = true;
    p.count_source = "src/sph/density.cc: NumNgb = NORM_COEFF * hfac * Density / Mass";
    p.bias_switch = "WENDLAND_BIAS_CORRECTION";
    p.bias_source = "src/sph/kernel.h, get_density_bias: eps100 (DesNumNgb / 100)^(-alpha) m W(0, H) off the density";
    p.self_bias = wendland_bias;
    p.dimensions = all;
    p.kernels = {{"CUBIC_SPLINE_KERNEL", "cubic_bspline", all},
                 {"WENDLAND_C2_KERNEL", "wendland_c2", dims},
                 {"WENDLAND_C4_KERNEL", "wendland_c4", dims},
                 {"WENDLAND_C6_KERNEL", "wendland_c6", dims}};
    set_neighbour_number(p);
    return p;
}

} // namespace sphkern
