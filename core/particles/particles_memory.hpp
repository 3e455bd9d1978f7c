// How many particles fit: derived from the memory this machine has available now
// (/proc/meminfo), or from a limit the user gives, instead of a fixed count.
#pragma once

#include <cstddef>

namespace sphkern {

// Bytes the particle engine needs per particle (positions, h, volumes, masses, the grid and
// its ghosts, every per-particle result).
inline constexpr std::size_t bytes_per_particle = 400;

// Sets the budget (0: the available memory less a quarter) from a number of GiB in
// [0, max_memory_limit_gib], checked by the caller (requests/source_request).
inline constexpr double max_memory_limit_gib = 1e6;
void set_memory_limit_gib(double gib);
std::size_t memory_limit_bytes();
std::size_t max_particles();
// The largest particle file read into memory: a third of the budget.
std::size_t particle_file_byte_limit();

} // namespace sphkern
