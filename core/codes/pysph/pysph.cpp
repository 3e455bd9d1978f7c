#include "codes/pysph/pysph.hpp"

#include <cmath>

namespace sphkern {

CodeProfile pysph_code()
{
    // Its kernels (pysph/base/kernels.py) and the dimensions their constructors accept: the
    // Wendland kernels raise outside 2D and 3D (the 1D ones are other classes, *_1D), and its
    // SuperGaussian is pi^(-D/2) (1 + D/2 - q^2) exp(-q^2): the paper's super_gaussian in 1D and
    // 3D, another function in 2D (pysph_super_gaussian).
    const std::vector<int> all{1, 2, 3}, plane_and_space{2, 3};
    CodeProfile p;
    p.name = "pysph";
    p.title = "PySPH";
    p.parameter = "hdx";
    p.parameter_help = "PySPH's hdx, h = hdx dx";
    p.source = "PySPH's examples: h = hdx dx with dx the particle spacing, support radius_scale h; its equations take "
               "W and its gradient at HIJ = (h_i + h_j) / 2 (pysph/sph/equation.py, precomputed_symbols)";
    p.dimensions = all;
    // Its weakly compressible schemes (WCSPH, TaitEOS); an ideal gas with its gas-dynamics schemes.
    p.rest_pressure = RestPressure::tait;
    p.coef_sound = 10 * std::sqrt(2.0);
    p.coef_sound_source = "its dam-break example's co = 10 sqrt(2 g H) (pysph/examples/dam_break_2d.py)";
    p.kernels = {{"CubicSpline", "cubic_bspline", all},
                 {"WendlandQuintic", "wendland_c2", plane_and_space},
                 {"WendlandQuinticC4", "wendland_c4", plane_and_space},
                 {"WendlandQuinticC6", "wendland_c6", plane_and_space},
                 {"QuinticSpline", "morris_quintic", all},
                 {"SuperGaussian", "pysph_super_gaussian", all},
                 {"SuperGaussian", "super_gaussian", {1, 3}}};
    p.user_kernels = true; // a scheme takes any kernel object with its kernel and gradient
    p.pair_mean = true;
    p.layout = CodeLayout::pysph;
    p.hdf5_suffix = ".hdf5";
    p.hdf5_suffix_reason = "PySPH's load reads a name ending in .hdf5";
    p.support_per_h = [](const Kernel& kernel, int) { return kernel.support(); }; // its radius_scale
    p.parameter_of = [](const Kernel&, int, double k, double spacing) { return k / spacing; };
    return p;
}

} // namespace sphkern
