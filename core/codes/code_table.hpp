// The SPH codes sphkern speaks (each in its folder codes/<name>/), and what the requests ask of
// one: its parameter on a lattice at rest with particle volume V = a_p d^D (m = rho0 V), the
// kernels and dimensions it runs, the support radius over the h its files store. Where a code
// solves for h from the SPH density (SWIFT, Phantom, GADGET), the density is the lattice's own
// SPH sum, rho = rho0 (1 + eps_rho(k)), not rho0: at the recommended k of cubic/fcc the two
// differ by about 0.2% in eta. The definitions, with H the support radius (sphkern's R h = R k d):
//   swift         eta   = h_s / (m / rho)^(1/D),  H = gamma h_s, gamma = R / (2 sigma)
//   phantom       hfact = h_p / (m / rho)^(1/D),  H = R h_p (its radkern is the kernel's R)
//   gadget2/4     nngb  = omega_D H^D rho / m,    the weighted neighbour number
//   pysph         hdx   = h_y / dx,               dx = V^(1/D), H = R h_y, a pair's h the mean
//   dualsphysics  coefh = h_d / (sqrt(D) dp),     dp = V^(1/D), H = 2 h_d
//   splishsplash  particle_radius = r / d,        H = 4 r, and the volume m / rho0 = 0.8 (2 r)^D:
//                 its one setting also sets the particle volume, whatever the lattice's is.
// Adding a code: its folder, and its row in code_table.cpp.
#pragma once

#include "codes/code_profile.hpp"
#include "kernels/kernel.hpp"
#include "support/text/value_checks.hpp"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace sphkern {

const std::vector<CodeProfile>& code_profiles();

// The profiles whose setting leaves the particle volume as it is (all but SPlisHSPlasH): the
// codes a recommended k is also given in.
const std::vector<const CodeProfile*>& study_codes();

// The profile of `name`; an unknown name is refused naming the source and listing the codes.
const CodeProfile& code_profile(const std::string& name, const ValueSource& source);

// Whether the code runs in `dimension` and ships the kernel there (its own function under the
// code's name). require_code_kernel refuses (exit 2) a dimension the code does not run, or a
// kernel it does not ship there, naming what it has; a code that takes a user's kernel (PySPH)
// takes any other with a warning that the code does not ship it.
bool code_ships(const CodeProfile& profile, const Kernel& kernel, int dimension);
void require_code_kernel(const CodeProfile& profile, const Kernel& kernel, int dimension);

// The support radius over the h the code stores in its files: SWIFT gamma, Phantom and PySPH
// the kernel's R, GADGET 1 (its h is the support), DualSPHysics 2.
double code_support_per_h(const CodeProfile& profile, const Kernel& kernel, int dimension);

// The particle volume, in d^D, a code's setting fixes (sets_volume): SPlisHSPlasH's
// 0.8 (2 r)^D for the particle radius r (in d).
double code_volume(const CodeProfile& profile, int dimension, double value);

// Refuses (Error(input)) a code whose setting fixes the volume where `what` holds the
// lattice's own volume (a window of k, a particle set, a relaxation).
void require_lattice_volume(const CodeProfile& profile, const std::string& what);

// The linear stability's pressure at rest as the code has it: gamma for an ideal gas (the
// user's, P0 / rho = c^2 / gamma), or for a Tait code the gamma = rho c^2 / P0 that its largest
// hydrostatic pressure at rest gives, CoefSound^2 (`coef_sound`, default the code's): the
// dispersion relation depends on P0 only through P0 / (rho c^2), its pairing term grows with
// it, and at P0 = 0 no kernel pairs, so the top of the range decides. Without a code, gamma.
struct StabilityPressure {
    double gamma = 5.0 / 3.0; // the dispersion relation's, 1 / (P0 / (rho c^2))
    bool tait = false;
    double coef_sound = 0; // Tait: c / sqrt(g H)
    std::string text;      // "an ideal gas at rest (gamma = 1.667)" or Tait's, for a person
};
StabilityPressure stability_pressure(const CodeProfile* code, double gamma, std::optional<double> coef_sound,
                                     const ValueSource& coef_sound_source);

// The code's parameter at k, the lattice's SPH density at rest being rho0 (1 + eps_rho).
double code_parameter(const CodeProfile& profile, const Kernel& kernel, int dimension, double a_p, double k,
                      double eps_rho);

// The k at which the code's parameter is `value`; eps_rho(k) gives the lattice's density
// error. Solved to 1e-12 in k where the parameter depends on the density; Error(input)
// naming `source` where no k up to k_max gives it.
double k_of_code_parameter(const CodeProfile& profile, const Kernel& kernel, int dimension, double a_p, double value,
                           double k_max, const std::function<double(double)>& eps_rho, const ValueSource& source);

} // namespace sphkern
