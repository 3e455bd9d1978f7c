#include "codes/gadget4/gadget4.hpp"

#include "codes/neighbour_number.hpp"

namespace sphkern {

CodeProfile gadget4_code()
{
    // 3D, and 2D with TWODIMS; the cubic spline and the Wendland kernels (sph/kernel.h).
    const std::vector<int> dims{2, 3};
    CodeProfile p;
    p.name = "gadget4";
    p.title = "GADGET-4";
    p.parameter = "nngb";
    p.parameter_help = "the weighted neighbour number";
    p.source = "Springel et al. 2021 (GADGET-4, MNRAS 506, 2871): DesNumNgb, the weighted neighbour number "
               "(4 pi / 3) H^3 rho / m";
    p.from_sph_density = true;
    p.count_source = "src/sph/density.cc: NumNgb = NORM_COEFF * hfac * Density / Mass";
    p.dimensions = dims;
    p.kernels = {{"CUBIC_SPLINE_KERNEL", "cubic_bspline", dims},
                 {"WENDLAND_C2_KERNEL", "wendland_c2", dims},
                 {"WENDLAND_C4_KERNEL", "wendland_c4", dims},
                 {"WENDLAND_C6_KERNEL", "wendland_c6", dims}};
    p.counts_neighbours = true;
    p.layout = CodeLayout::gadget;
    p.hdf5_suffix = ".hdf5";
    p.hdf5_suffix_reason = "GADGET opens <InitCondFile>.hdf5 for HDF5 initial conditions (ICFormat 3)";
    p.support_per_h = [](const Kernel&, int) { return 1.0; }; // its SmoothingLength is the support radius
    p.parameter_of = [](const Kernel& kernel, int dim, double k, double spacing) {
        return neighbour_number(dim, kernel.support() * k, spacing);
    };
    return p;
}

} // namespace sphkern
