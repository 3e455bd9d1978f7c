#include "cli/source_options.hpp"

#include "cli/command.hpp"
#include "lattices/lattice.hpp"
#include "particles/formats/particle_arrays.hpp"
#include "particles/formats/particle_files.hpp"
#include "requests/source_request.hpp"
#include "support/error.hpp"
#include "support/io/sha256.hpp"
#include "support/text/value_checks.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

namespace sphkern::cli {

void add_source_options(Command c, SourceOptions& o)
{
    c.add_option("source", o.source,
                 "A lattice (name or file), poisson, or a particle file (.h5/.hdf5, .csv, .vtk, a GADGET binary "
                 "snapshot, a Phantom dump)")
        .required();
    c.add_option("--size", o.size, "Lattice: cells of the periodic block, N1,N2[,N3]");
    c.add_option("--cell", o.cell,
                 "Lattice: the cell --size counts, primitive (default) or rectangular (a rectangular box)");
    c.add_option("--sigma", o.sigma, "Lattice: Gaussian displacement per axis, in units of d");
    c.add_option("--seed", o.seed, "Lattice and poisson: the random seed").capture_default_str();
    c.add_option("--count", o.count, "Poisson: number of particles");
    c.add_option("--dim", o.dim,
                 "Poisson: 2 or 3 (default 3); file: 2 reads a 3-column set with one constant coordinate");
    c.add_option("--box", o.box, "Poisson: the box sides (default 1); file: a periodic box Lx,Ly[,Lz] from the origin");
    c.add_option("--particle-radius", o.particle_radius,
                 "SPlisHSPlasH VTK file: the scene's particle radius r (the file holds none); h = r, support 4 r");
    c.add_option("--array", o.array,
                 "PySPH file: the particle array, or A,B,...: measured on A, with the particles of all as neighbours");
}

ParticleSource source_of(const SourceOptions& o)
{
    return particle_source_of({o.source, o.size, o.box, o.array, o.cell, o.sigma, o.seed, o.count, o.dim,
                               o.particle_radius},
                              source_sources(FrontEnd::command_line));
}

std::unique_ptr<FileDigest> start_source_digest(const SourceOptions& o)
{
    if (source_kind(o.source) != SourceKind::file) return nullptr;
    return std::make_unique<FileDigest>(particle_file_named(o.source));
}

nlohmann::json source_inputs(const SourceOptions& o, const Kernel& kernel, FileDigest* digest)
{
    const auto kind = source_kind(o.source);
    std::optional<Lattice> lattice;
    if (kind == SourceKind::lattice) lattice = load_lattice(o.source);
    nlohmann::json inputs = command_inputs(&kernel, lattice ? &*lattice : nullptr);
    nlohmann::json source = {{"spec", o.source}, {"size", o.size}, {"sigma", o.sigma}, {"seed", o.seed},
                             {"count", o.count}, {"box", o.box},   {"array", o.array}};
    if (!o.cell.empty()) source["cell"] = o.cell;
    if (o.particle_radius) source["particle_radius"] = *o.particle_radius;
    if (kind == SourceKind::file)
        source["sha256"] = digest ? digest->get() : file_sha256_hex(particle_file_named(o.source));
    inputs["particles"] = source;
    return inputs;
}

} // namespace sphkern::cli
