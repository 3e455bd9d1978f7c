#include "codes/swift/swift.hpp"

#include "codes/swift/swift_gamma.hpp"

namespace sphkern {

CodeProfile swift_code()
{
    // Its kernels (kernel_hydro.h): the splines in 1D, 2D and 3D; the Wendland kernels have no 1D form there.
    const std::vector<int> all{1, 2, 3}, plane_and_space{2, 3};
    CodeProfile p;
    p.name = "swift";
    p.title = "SWIFT";
    p.parameter = "eta";
    p.parameter_help = "SWIFT's eta, h = eta (m / rho)^(1/D)";
    p.source = "SWIFT's hydro documentation: h = eta (m / rho)^(1/D) solved with the SPH density, H = gamma h "
               "(Dehnen & Aly 2012)";
    p.from_sph_density = true;
    p.counts = NeighbourCount::number;
    p.count_source = "runner_ghost.c, runner_do_ghost: h^D sum_j W_ij = eta^D with wcount (hydro_end_density), by "
                     "mass only with SPH:use_mass_weighted_num_ngb";
    // runner_ghost.c then takes wcount = rho / m_i: h^D sum_j (m_j / m_i) W_ij = eta^D, h = eta (m_i / rho_i)^(1/D).
    p.count_switch = "SPH:use_mass_weighted_num_ngb: 1";
    p.dimensions = all;
    p.kernels = {{"Cubic spline (M4)", "cubic_bspline", all},     {"Quartic spline (M5)", "quartic_bspline", all},
                 {"Quintic spline (M6)", "morris_quintic", all},  {"Wendland C2", "wendland_c2", plane_and_space},
                 {"Wendland C4", "wendland_c4", plane_and_space}, {"Wendland C6", "wendland_c6", plane_and_space}};
    p.layout = CodeLayout::swift;
    p.support_per_h = swift_gamma;
    p.parameter_of = [](const Kernel& kernel, int dim, double k, double spacing) {
        return kernel.support() * k / swift_gamma(kernel, dim) / spacing;
    };
    return p;
}

} // namespace sphkern
