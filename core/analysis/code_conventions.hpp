// sphkern's resolution (h = k d, support radius H = R h) in the conventions of the SPH codes
// users run. With V = a_p d^D the volume per particle (m / rho0) and dp = V^(1/D) its spacing:
//   PySPH         hdx = h / dp                 (its kernels' support is R h, as sphkern's)
//   DualSPHysics  coefh = H / (2 sqrt(D) dp)   (h = coefh sqrt(D) dp, support 2h)
//   SWIFT         eta = H / (gamma V^(1/D))    (h = eta (m/rho)^(1/D), support gamma h)
//   GADGET        N_ngb = omega_D H^D / V      (its h is the support radius; omega_D the unit ball)
//   SPlisHSPlasH  H / r_p = 2 H / dp           (it stores no h; its support is 4 r_p, r_p = dp / 2)
// SWIFT's gamma = H / (2 sigma), sigma^2 the kernel's variance per dimension (Dehnen & Aly
// 2012): computed from the kernel, so it exists for every kernel.
#pragma once

#include "kernels/kernel.hpp"

#include <string>
#include <vector>

namespace sphkern {

struct CodeConvention {
    std::string name;     // "pysph", "dualsphysics", "swift", "gadget", "splishsplash"
    std::string quantity; // "hdx", "coefh", "eta", "N_ngb", "H/r_p"
};
const std::vector<CodeConvention>& code_conventions();

// Throws Error(usage) naming `what` for a name not in code_conventions().
const CodeConvention& code_convention(const std::string& name, const std::string& what);

// SWIFT's kernel gamma H / (2 sigma) of the kernel in `dim` dimensions (by quadrature); NaN
// when the kernel's second moment is not positive (the 2D super-Gaussian's is -1).
double swift_gamma(const Kernel& kernel, int dim);

// The value of `convention` at k, with a_p the volume coefficient (V = a_p d^D); NaN where
// the convention is not defined for the kernel (see swift_gamma).
double in_convention(const CodeConvention& convention, const Kernel& kernel, int dim, double a_p, double k);
// Why a convention is not defined for a kernel, empty when it is.
std::string convention_undefined(const CodeConvention& convention, const Kernel& kernel, int dim);

} // namespace sphkern
