// Where a particle set comes from (`particles`, `relax`, a study's sources): a lattice block,
// a Poisson set or a file, each value checked once, named as the front end names it, and
// the lattice read once.
#pragma once

#include "particles/formats/snapshot_rows.hpp"
#include "particles/sources/particle_source.hpp"
#include "support/text/value_checks.hpp"

#include <cstddef>
#include <memory>
#include <optional>
#include <string>

namespace sphkern {

struct SourceSources {
    ValueSource size, sigma, count, dim, box, array, particle_radius, cell;
    std::string budget; // how the front end sets the memory budget, if it can: "--memory-limit"
};
SourceSources source_sources(FrontEnd front_end);

// A source as the front end gives it: a lattice (name or file), poisson or a particle file,
// and the settings of its kind, lists as texts ("4,4,4" cells, "1,1" box sides).
struct SourceArguments {
    std::string spec, size, box, array, cell;
    double sigma = 0;
    unsigned long long seed = 1, count = 0;
    int dim = 0;
    std::optional<double> particle_radius;
};

// The source: a name that is no lattice refused with the shipped ones (a typo more often than a
// lattice without its size), and settings that do not fit its kind refused, named by `sources`.
ParticleSource particle_source_of(const SourceArguments& given, const SourceSources& sources);

// What needs no lattice or file: cells 1 to 1e6, sigma [0, 10] (units of d); a Poisson
// dimension of 2 or 3, count 2 to 2^40; box sides positive and finite; a file's list of
// arrays well formed and its particle radius positive and finite.
void check_particle_source(const ParticleSource& source, const SourceSources& sources);

// Checks a memory budget in GiB (0: from the available memory) and sets it for the process.
void set_memory_budget(double gib, const ValueSource& source);

// Checked, then made or read: a block takes as many cell counts as its lattice has dimensions,
// and a block or a Poisson set over the memory budget is refused before it is made.
ParticleSet load_source(const ParticleSource& source, const SourceSources& sources, int threads);

// A particle file that is a SWIFT or GADGET snapshot declaring more particles than the memory
// budget holds: opened to be read in slabs (particles/slabs), its box the one given where a box
// is given; none for any other source. A dimension given for it is refused (finding its one
// constant coordinate would read it whole).
std::unique_ptr<SnapshotRows> snapshot_in_slabs(const ParticleSource& source, const SourceSources& sources);

} // namespace sphkern
