// A set of particles with no lattice behind it: positions in D = 2 or 3 dimensions,
// optionally a periodic box (a parallelepiped: minimum-image displacements), and what a
// file may carry per particle (smoothing length, mass, density). Section 11 of
// share/docs/method.md says what sphkern computes on it.
#pragma once

#include "support/process/first_touch.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace sphkern {

// A periodic cell: its edge vectors are the columns of `edges` (in 2D the third is e_z and
// its z is ignored); positions are wrapped into it.
struct PeriodicBox {
    Eigen::Matrix3d edges = Eigen::Matrix3d::Identity();
    double volume(int dimension) const;
    // The distance between opposite faces along each edge: no displacement longer than
    // half the smallest width has two images inside a sphere around a particle.
    double smallest_width(int dimension) const;
};

struct ParticleSet {
    std::string name; // the file, lattice or "poisson", for messages
    // Other files the reader opened through the file (HDF5 external links, virtual datasets):
    // inputs too, which no output may replace.
    std::vector<std::string> linked_files;
    int dimension = 3;
    ParticleValues x, y, z;          // z is 0 in 2D; first touched by the threads that fill them
    ParticleValues h, mass, density; // each empty or one value per particle
    std::optional<PeriodicBox> box;
    double support_per_h = 0; // a file's own convention (SWIFT's kernel gamma), 0 if unknown
    // A file with no h whose code's support is this many particle radii, a radius the file does
    // not hold (SPlisHSPlasH: 4); 0 for others. Without a radius such a set needs --h-over-l or --nh.
    double support_per_radius = 0;
    // The kernel that convention belongs to: as the file names it ("Wendland C2") and as
    // sphkern does ("wendland_c2", empty if sphkern ships no such kernel); empty if not said.
    std::string file_kernel, file_kernel_name;
    // The simulation time the file's header gives (SWIFT and GADGET /Header Time, PySPH's
    // solver_data t, GADGET's binary header, Phantom's time); none for other sets.
    std::optional<double> time;
    double spacing = 0;                                  // a lattice's nearest-neighbour distance d, 0 for other sets
    Eigen::Vector3d gravity = Eigen::Vector3d(0, 0, -1); // the lattice's, else -y (2D) or -z (3D)

    // The last this many particles are neighbours only (a PySPH file's other arrays: walls and
    // solids): they enter the others' sums but are not measured; the statistics are over the rest.
    std::size_t neighbours_only = 0;

    // Each particle's row in its file where the set is a part of a larger one (a slab, a chunk
    // read); empty: the row is the index. Errors name particles by it.
    std::vector<std::uint64_t> ids;

    // A PySPH file's arrays read, in order, each with its first particle's index in the set;
    // empty for other sets. Errors name a particle within its array.
    std::vector<std::pair<std::string, std::size_t>> arrays;

    std::size_t size() const { return x.size(); }
    std::uint64_t id(std::size_t i) const { return ids.empty() ? i : ids[i]; }
    // "particle 517", or "particle 5 of array \"solid\"" in a set of several arrays.
    std::string particle(std::size_t i) const;
    std::size_t measured() const { return x.size() - neighbours_only; }
    Eigen::Vector3d position(std::size_t i) const { return {x[i], y[i], z[i]}; }
};

// Checks what every source must give: D, at least two particles, finite coordinates inside
// the box (wrapped into it), positive finite h, masses and densities. Throws Error(input)
// naming the set, the field and the particle id (the lowest one, on any number of threads).
void validate_particle_set(ParticleSet& set, int threads = 1);
// Its per-particle part, for a part of a set read chunk by chunk: finite coordinates, positive
// finite h, masses and densities, and each particle wrapped into the box.
void validate_particle_values(ParticleSet& set, int threads = 1);

// The box shared out equally, V = box / N, and its D-th root l = V^(1/D), the mean spacing
// (a set with a box).
double mean_volume(const ParticleSet& set);
double mean_spacing(const ParticleSet& set);

// Moves every particle of a set with a box into it (by whole edges). Throws Error(input) for
// a particle more than one box outside: in a file that is a wrong box, not rounding. A set
// sphkern displaces itself (a disturbed lattice block) is periodic by construction: `any_distance`.
enum class WrapReach { one_box, any_distance };
void wrap_into_box(ParticleSet& set, WrapReach reach = WrapReach::one_box, int threads = 1);

} // namespace sphkern
