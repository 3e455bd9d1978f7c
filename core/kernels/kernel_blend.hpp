// Blends: W = (1 - alpha) W_A + alpha W_B of two kernels, each cut at its own support.
// The parameter alpha may be any real number; the blend's support is the larger R.
#pragma once

#include "kernels/kernel.hpp"

#include <memory>

namespace sphkern {

// Throws Error(input) if the two kernels share no dimension.
std::shared_ptr<const KernelDefinition> make_blend(const Kernel& a, const Kernel& b);

} // namespace sphkern
