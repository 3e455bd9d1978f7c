// DualSPHysics: h = coefh sqrt(D) dp from the particle spacing dp, support 2 h.
#pragma once

#include "codes/code_profile.hpp"

namespace sphkern {

CodeProfile dualsphysics_code();

} // namespace sphkern
