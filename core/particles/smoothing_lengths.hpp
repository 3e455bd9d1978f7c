// sphkern's h for every particle of a set (support radius R h): from eta, from a neighbour
// number, from k on a lattice, or from the file's own h under a stated convention.
#pragma once

#include "kernels/kernel.hpp"
#include "particles/particle_set.hpp"
#include "particles/per_particle.hpp"

#include <vector>

namespace sphkern {

class MeasureCollector; // particles/particle_measures.hpp

// density: h_i = value (m_i / rho_i)^(1/D) with rho_i the SPH density at h_i (density_smoothing.hpp).
enum class SmoothingRule { eta, nh, k, file, density };

// The h of a pair in the sums: the particle's own h_i (the gather form of SWIFT, Phantom and
// GADGET), or the mean (h_i + h_j) / 2 (PySPH's HIJ).
enum class PairSmoothing { own, mean };

struct SmoothingSpec {
    SmoothingRule rule = SmoothingRule::eta;
    double value = 1.2;       // eta, N_H, k or the density rule's coefficient; unused for `file`
    double support_per_h = 0; // `file`: the support radius is this times the stored h; 0: the file's own
    PairSmoothing pair = PairSmoothing::own;
    bool by_number = false; // `density`: the solve counts each neighbour once, not its mass (SWIFT, GADGET-2)
    double self_weight =
        1; // `density`: the weight of a particle's own term in its density (GADGET-4's bias correction)
};

// N_H = c_D (R eta)^D, the mean number of neighbours inside the support at uniform density
// (Dehnen & Aly 2012; c_2 = pi, c_3 = 4 pi / 3), and its inverse.
double neighbour_number(double eta, double support, int dimension);
double eta_for_neighbour_number(double nh, double support, int dimension);

// h of every particle, filled on `threads` threads; `mean_volume` is V̄ of h = eta V̄^(1/D).
// The spec as checked against the set by requests/smoothing_request.hpp (a k without a
// lattice, a file h without a convention: std::logic_error). With `measures`, a rule that
// solves h from the SPH density measures each particle as it solves it
// (density_smoothing_lengths); the other rules do not take one.
PerParticle smoothing_lengths(const ParticleSet& set, const Kernel& kernel, const SmoothingSpec& spec,
                              double mean_volume, int threads = 1, MeasureCollector* measures = nullptr);

} // namespace sphkern
