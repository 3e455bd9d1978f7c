#include "codes/phantom/phantom.hpp"

namespace sphkern {

CodeProfile phantom_code()
{
    // Phantom is a 3D code (its config.F90 fixes ndim = 3); one kernel file each (kernel_*.f90).
    const std::vector<int> space{3};
    CodeProfile p;
    p.name = "phantom";
    p.title = "Phantom";
    p.parameter = "hfact";
    p.parameter_help = "Phantom's hfact, h = hfact (m / rho)^(1/D)";
    p.source = "Price et al. 2018 (Phantom, PASA 35, e031): rho = m (hfact / h)^D with the SPH density, support "
               "radkern h";
    p.from_sph_density = true;
    p.count_source = "part.F90, rhoh: rho = m (hfact / h)^3 against dens.F90's sum_j m_j W_ij";
    p.dimensions = space;
    p.kernels = {{"cubic", "cubic_bspline", space},    {"quartic", "quartic_bspline", space},
                 {"quintic", "morris_quintic", space}, {"WendlandC2", "wendland_c2", space},
                 {"WendlandC4", "wendland_c4", space}, {"WendlandC6", "wendland_c6", space}};
    p.layout = CodeLayout::phantom; // a full dump (write_fulldump), which read_dump starts from
    p.support_per_h = [](const Kernel& kernel, int) { return kernel.support(); }; // its radkern
    p.parameter_of = [](const Kernel&, int, double k, double spacing) { return k / spacing; };
    return p;
}

} // namespace sphkern
