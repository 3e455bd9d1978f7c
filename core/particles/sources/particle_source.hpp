// Where a particle set comes from: a lattice block, a Poisson set or a file, as one value
// that the command line, a study and Python all build.
#pragma once

#include "particles/formats/particle_files.hpp"
#include "particles/particle_set.hpp"
#include "particles/sources/lattice_particles.hpp"
#include "particles/sources/poisson_particles.hpp"

#include <optional>
#include <string>

namespace sphkern {

enum class SourceKind { lattice, poisson, file };

struct ParticleSource {
    SourceKind kind = SourceKind::lattice;
    std::string spec;                   // the lattice (name or file) or the particle file
    LatticeBlockSpec block;             // lattice
    std::size_t cell_counts = 0;        // lattice: how many counts were given (block.cells holds 1 for the rest)
    PoissonSpec poisson;                // poisson
    ParticleFileOptions file;           // file
    std::optional<Eigen::Vector3d> box; // a periodic rectangular box for a file (or poisson's sides)
};

// "poisson", a particle file (by extension or content), else a lattice name or file.
SourceKind source_kind(const std::string& spec);

// Loads (generates) and validates the set on `threads` threads (0: every core); the set does
// not depend on the number. The source as checked by requests/source_request.hpp; a file's
// size is checked against the memory budget as it is read.
ParticleSet load_particles(const ParticleSource& source, int threads = 0);

} // namespace sphkern
