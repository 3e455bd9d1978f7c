// Phantom: h = hfact (m / rho)^(1/D) solved with the SPH density, H = radkern h; 3D only.
#pragma once

#include "codes/code_profile.hpp"

namespace sphkern {

CodeProfile phantom_code();

} // namespace sphkern
