// SWIFT: h = eta (m / rho)^(1/D) solved with the SPH density, H = gamma h.
#pragma once

#include "codes/code_profile.hpp"

namespace sphkern {

CodeProfile swift_code();

} // namespace sphkern
