// The volume V_j of every particle: the box shared out equally, the file's m / rho, or the
// particle's Voronoi cell in the periodic box.
#pragma once

#include "particles/particle_set.hpp"
#include "particles/per_particle.hpp"

#include <string>
#include <vector>

namespace sphkern {

enum class VolumeModel { uniform, file, voronoi };

VolumeModel parse_volume_model(const std::string& name); // Error(usage) for another name
const char* volume_model_name(VolumeModel model);

// The model a set gets when none is asked for: m / rho where the file has both, else uniform.
VolumeModel default_volume_model(const ParticleSet& set);

// Filled on `threads` threads. Throws Error(input) where the set lacks what the model needs (a
// box, masses and densities).
PerParticle particle_volumes(const ParticleSet& set, VolumeModel model, int threads = 1);

// The Voronoi cell of every particle in the periodic box (voro++; a 2D set as a slab one
// spacing thick, whose cells are prisms of the 2D cells).
std::vector<double> voronoi_volumes(const ParticleSet& set);

} // namespace sphkern
