// How many wave vectors a stability scan over k looks at first, and the limit for them: one
// count for `stability --kmin/--kmax`, `roots --stability`, the Python module and studies.
#pragma once

namespace sphkern {

inline constexpr double max_stability_points = 1e8; // wave vectors over all k samples

// (steps + 1) k samples times the first zone grid (`grid` per reciprocal axis, 0: the
// default, 8 in 3D and 32 in 2D); `dimension` 0 counts the larger of 2D and 3D.
double stability_wave_vectors(int steps, int grid, int dimension);

// Throws Error(input), naming `who` (e.g. "stability --kmin/--kmax"), if over the limit.
void check_stability_budget(const char* who, int steps, int grid, int dimension);

} // namespace sphkern
