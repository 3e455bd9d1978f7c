#include "codes/splishsplash/splishsplash.hpp"

#include <cmath>

namespace sphkern {

CodeProfile splishsplash_code()
{
    // SPHKernels.h: the cubic spline, the Wendland quintic C2, poly6 and spiky in 3D; the 2D
    // simulation has only the cubic spline and the Wendland quintic C2 (CubicKernel2D, WendlandQuinticC2Kernel2D).
    CodeProfile p;
    p.name = "splishsplash";
    p.title = "SPlisHSPlasH";
    p.parameter = "particle_radius";
    p.parameter_help = "its particle radius r in d, support 4 r and volume 0.8 (2 r)^D";
    p.source = "SPlisHSPlasH's FluidModel: support radius 4 r for the particle radius r, particle volume 0.8 (2 r)^D "
               "(its kernels: cubic spline, Wendland quintic C2, poly6, spiky)";
    p.dimensions = {2, 3};
    p.kernels = {{"CubicKernel", "cubic_bspline", {2, 3}},
                 {"WendlandQuinticC2Kernel", "wendland_c2", {2, 3}},
                 {"Poly6Kernel", "muller_poly6", {3}},
                 {"SpikyKernel", "desbrun_spiky", {3}}};
    p.sets_volume = true;
    p.support_per_h = [](const Kernel&, int) { return 4.0; }; // its particle radius as h
    p.parameter_of = [](const Kernel& kernel, int, double k, double) { return kernel.support() * k / 4; };
    return p;
}

double splishsplash_volume(int dim, double radius) { return 0.8 * std::pow(2 * radius, dim); }

} // namespace sphkern
