// How much work a stability request asks for, and the limits for it: one count for
// `stability` (one k or --kmin/--kmax), `roots --stability`, the Python module and studies.
#pragma once

#include "kernels/kernel.hpp"
#include "lattices/lattice.hpp"

#include <string>

namespace sphkern {

inline constexpr double max_stability_points = 1e8;          // wave vectors over all k samples
inline constexpr double max_stability_neighbour_terms = 5e8; // neighbours x wave vectors over all k samples
inline constexpr double max_dispersion_neighbours = 4e6;     // neighbours kept in memory for one k (all sites)

// (steps + 1) k samples times the first zone grid (`grid` per reciprocal axis, 0: the
// default, 8 in 3D and 32 in 2D); `dimension` 0 counts the larger of 2D and 3D.
double stability_wave_vectors(int steps, int grid, int dimension);

// Throws Error(input), naming `who` (e.g. "stability --kmin/--kmax"), if over the limit; `how`
// (work_budget.hpp) names the options that make the work smaller.
void check_stability_budget(const char* who, int steps, int grid, int dimension, const std::string& how = "");

// The neighbours of every site within the kernel's support at k: the ball of radius R k d over
// the volume per site, times the sites (each wave vector sums over all of them).
double dispersion_neighbours(const Kernel& kernel, const Lattice& lattice, double k);

// Throws Error(input) if the neighbour list at k would not fit the limit (its memory).
void check_dispersion_neighbours(const Kernel& kernel, const Lattice& lattice, double k);

// The neighbour sums of the first zone grid over the steps + 1 samples of [k_min, k_max]
// (steps 0: k_min alone); throws Error(input), naming `who`, over the limit. Checked before
// any neighbour is listed: at k = 60 one zone scan otherwise sums for many minutes.
double stability_neighbour_terms(const Kernel& kernel, const Lattice& lattice, double k_min, double k_max, int steps,
                                 int grid);
void check_stability_work(const char* who, const Kernel& kernel, const Lattice& lattice, double k_min, double k_max,
                          int steps, int grid, const std::string& how = "");
// The same limit for `wave_vectors` wave vectors at one k (a dispersion path).
void check_dispersion_work(const char* who, const Kernel& kernel, const Lattice& lattice, double k, double wave_vectors,
                           const std::string& how = "");

} // namespace sphkern
