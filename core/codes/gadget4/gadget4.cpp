#include "codes/gadget4/gadget4.hpp"

#include "codes/neighbour_number.hpp"

namespace sphkern {

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
    p.dimensions = all;
    p.kernels = {{"CUBIC_SPLINE_KERNEL", "cubic_bspline", all},
                 {"WENDLAND_C2_KERNEL", "wendland_c2", dims},
                 {"WENDLAND_C4_KERNEL", "wendland_c4", dims},
                 {"WENDLAND_C6_KERNEL", "wendland_c6", dims}};
    set_neighbour_number(p);
    return p;
}

} // namespace sphkern
