// SPlisHSPlasH: support radius 4 r for the particle radius r, particle volume 0.8 (2 r)^D.
#pragma once

#include "codes/code_profile.hpp"

namespace sphkern {

CodeProfile splishsplash_code();

// The particle volume, in d^D, that the particle radius r (in d) fixes: 0.8 (2 r)^D.
double splishsplash_volume(int dimension, double radius);

} // namespace sphkern
