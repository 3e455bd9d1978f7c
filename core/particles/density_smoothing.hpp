// h from the SPH density, as SWIFT, Phantom and GADGET set it: every particle's
// h_i = c (m_i / rho_i)^(1/D), with rho_i = sum_j m_j W(|r_ij|, h_i) its SPH density at its
// own h (the particle itself included), solved together for the whole set. Counted by number
// (SWIFT, GADGET-2), h_i = c (1 / n_i)^(1/D) with n_i = sum_j W(|r_ij|, h_i): the same solve with
// every mass equal.
#pragma once

#include "kernels/kernel.hpp"
#include "particles/particle_measures.hpp"
#include "particles/particle_set.hpp"
#include "particles/per_particle.hpp"

namespace sphkern {

// Passes of the density at the current h, each followed by a step of every h towards
// h_i = c (m_i / rho_i)^(1/D), until every residual is below a relative 1e-12 (the fixed
// point the codes' own Newton steps reach too); Error(input) if 100 passes do not get there. The masses are the set's,
// or the mean volume (rho0 = 1) where it has none or the solve counts by number. Every particle is measured: a set with
// neighbours-only particles is refused (their h is not the solve's). `self_weight` scales each
// particle's own term m_i W(0, h_i) in rho_i: below 1 where a code subtracts a bias from it
// (GADGET-4's WENDLAND_BIAS_CORRECTION).
// With `measures`, each particle is measured as it is solved, from the neighbours its solve
// gathered (no second search); the collector's masses must be the solve's where it has any.
PerParticle density_smoothing_lengths(const Kernel& kernel, const ParticleSet& set, double coefficient,
                                      double mean_volume, int threads, bool by_number = false, double self_weight = 1,
                                      MeasureCollector* measures = nullptr);

} // namespace sphkern
