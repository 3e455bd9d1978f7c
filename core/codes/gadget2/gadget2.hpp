// GADGET-2: the weighted neighbour number (4 pi / 3) H^3 rho / m solved with the SPH density, H
// its smoothing length (the support radius).
#pragma once

#include "codes/code_profile.hpp"

namespace sphkern {

CodeProfile gadget2_code();

} // namespace sphkern
