#include "particles/sources/particle_source.hpp"

#include "lattices/lattice.hpp"
#include "particles/particles_memory.hpp"
#include "support/process/parallel_for.hpp"

namespace sphkern {

SourceKind source_kind(const std::string& spec)
{
    if (spec == "poisson") return SourceKind::poisson;
    if (particle_file_format(spec)) return SourceKind::file;
    // Lattice files are JSON; any other path is a particle file (refused by name if it is none).
    const bool path = spec.find('/') != std::string::npos;
    return path && !spec.ends_with(".json") ? SourceKind::file : SourceKind::lattice;
}

ParticleSet load_particles(const ParticleSource& source, int threads)
{
    threads = worker_threads(threads);
    switch (source.kind) {
    case SourceKind::lattice:
        return lattice_particles(block_cell(load_lattice(source.spec), source.block), source.block, threads);
    case SourceKind::poisson: return poisson_particles(source.poisson, threads);
    case SourceKind::file: break;
    }
    ParticleFileOptions options = source.file;
    options.max_particles = max_particles();
    ParticleSet set = read_particle_file(source.spec, options);
    if (source.box) {
        PeriodicBox box;
        for (int a = 0; a < set.dimension; ++a) box.edges(a, a) = (*source.box)[a];
        set.box = box;
    }
    validate_particle_set(set, threads);
    return set;
}

} // namespace sphkern
