// GADGET's weighted neighbour number: the volume of the support sphere (disc, segment) in
// particle volumes, omega_D H^D rho / m with omega_D = 2, pi, 4 pi / 3 in 1D, 2D, 3D.
#pragma once

#include "codes/code_profile.hpp"

namespace sphkern {

// omega_D H^D / s^D for the support radius H and the spacing s = (m / rho)^(1/D), both in d.
double neighbour_number(int dimension, double support, double spacing);

// What both GADGETs share: the neighbour number as the parameter, the SmoothingLength they
// store as the support radius, their HDF5 layout and its name (<InitCondFile>.hdf5).
void set_neighbour_number(CodeProfile& profile);

} // namespace sphkern
