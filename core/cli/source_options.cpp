#include "cli/source_options.hpp"

#include "cli/command.hpp"
#include "lattices/lattice.hpp"
#include "particles/formats/particle_arrays.hpp"
#include "particles/formats/particle_files.hpp"
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
    c.add_option("source", o.source, "A lattice (name or file), poisson, or a particle file (.h5/.hdf5, .csv, .vtk, a GADGET binary snapshot, a Phantom dump)")
        .required();
    c.add_option("--size", o.size, "Lattice: cells of the periodic block, N1,N2[,N3]");
    c.add_option("--cell", o.cell, "Lattice: the cell --size counts, primitive (default) or rectangular (a rectangular box)");
    c.add_option("--sigma", o.sigma, "Lattice: Gaussian displacement per axis, in units of d");
    c.add_option("--seed", o.seed, "Lattice and poisson: the random seed").capture_default_str();
    c.add_option("--count", o.count, "Poisson: number of particles");
    c.add_option("--dim", o.dim, "Poisson: 2 or 3 (default 3); file: 2 reads a 3-column set with one constant coordinate");
    c.add_option("--box", o.box, "Poisson: the box sides (default 1); file: a periodic box Lx,Ly[,Lz] from the origin");
    c.add_option("--particle-radius", o.particle_radius,
                 "SPlisHSPlasH VTK file: the scene's particle radius r (the file holds none); h = r, support 4 r");
    c.add_option("--array", o.array,
                 "PySPH file: the particle array, or A,B,...: measured on A, with the particles of all as neighbours");
}

namespace {

// The options of a file source: its arrays, dimension, box and particle radius.
void file_source(const SourceOptions& o, ParticleSource& source)
{
    source.file.array = o.array;
    source.file.particle_radius = o.particle_radius;
    if (o.dim) source.file.dimension = o.dim;
    if (!o.box.empty()) {
        const auto sides = parse_number_list(o.box, ValueSource::option("--box"), 2, 3);
        source.box = Eigen::Vector3d(sides[0], sides[1], sides.size() == 3 ? sides[2] : 1.0);
    }
}

} // namespace

ParticleSource source_of(const SourceOptions& o)
{
    ParticleSource source;
    source.spec = o.source;
    source.kind = source_kind(o.source);
    // A word that names no lattice is a typo more often than a lattice without its --size.
    auto names = shipped_lattice_names();
    if (source.kind == SourceKind::lattice && !o.source.ends_with(".json") && std::find(names.begin(), names.end(), o.source) == names.end()) {
        names.push_back("poisson");
        throw Error(ExitCode::input, fmt::format("unknown source \"{}\"{}; expected poisson, a lattice ({}) or a "
                                                 "particle file",
                                                 o.source, did_you_mean(o.source, names), fmt::join(names.begin(), names.end() - 1, ", ")));
    }
    if (source.kind != SourceKind::lattice && !o.size.empty())
        throw Error(ExitCode::usage, "--size cuts a lattice into a block; " + o.source + " is not a lattice");
    if (source.kind != SourceKind::lattice && !o.cell.empty())
        throw Error(ExitCode::usage, "--cell is the cell of a lattice block; " + o.source + " is not a lattice");
    if (!o.cell.empty() && o.cell != "primitive" && o.cell != "rectangular")
        throw Error(ExitCode::usage, "--cell: \"" + o.cell + "\" is unknown, expected primitive or rectangular");
    source.block.rectangular = o.cell == "rectangular";
    if (source.kind != SourceKind::poisson && o.count)
        throw Error(ExitCode::usage, "--count is for poisson sets");
    if (source.kind == SourceKind::lattice) {
        if (o.size.empty()) throw Error(ExitCode::usage, "a lattice source needs --size N1,N2[,N3] (cells of the periodic block)");
        const auto cells = parse_number_list(o.size, ValueSource::option("--size"), 2, 3);
        for (std::size_t a = 0; a < cells.size(); ++a) {
            if (cells[a] != std::floor(cells[a]) || std::abs(cells[a]) > 1e15)
                throw Error(ExitCode::usage, "--size " + o.size + ": expected whole numbers of cells");
            source.block.cells[a] = static_cast<long long>(cells[a]);
        }
        source.cell_counts = cells.size();
        source.block.sigma = o.sigma;
        source.block.seed = o.seed;
    } else if (o.sigma != 0) {
        throw Error(ExitCode::usage, "--sigma disturbs a lattice; " + o.source + " is not a lattice");
    }
    if (source.kind == SourceKind::poisson) {
        if (!o.count) throw Error(ExitCode::usage, "a poisson set needs --count N");
        source.poisson.count = static_cast<std::size_t>(o.count);
        source.poisson.dimension = o.dim ? o.dim : 3;
        source.poisson.seed = o.seed;
        if (!o.box.empty()) {
            const auto sides = parse_number_list(o.box, ValueSource::option("--box"), 1, 3);
            for (int a = 0; a < 3; ++a)
                source.poisson.box[a] = sides[sides.size() == 1 ? 0 : std::min<std::size_t>(static_cast<std::size_t>(a), sides.size() - 1)];
            if (sides.size() != 1 && static_cast<int>(sides.size()) != source.poisson.dimension)
                throw Error(ExitCode::usage, "--box " + o.box + ": give one side or one per dimension");
        }
    }
    if (source.kind == SourceKind::file) file_source(o, source);
    else if (!o.array.empty())
        throw Error(ExitCode::usage, "--array chooses a PySPH particle array; " + o.source + " is not a file");
    else if (o.particle_radius)
        throw Error(ExitCode::usage, "--particle-radius gives the h of a SPlisHSPlasH file; " + o.source + " is not a file");
    return source;
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
                             {"count", o.count}, {"box", o.box}, {"array", o.array}};
    if (!o.cell.empty()) source["cell"] = o.cell;
    if (o.particle_radius) source["particle_radius"] = *o.particle_radius;
    if (kind == SourceKind::file) source["sha256"] = digest ? digest->get() : file_sha256_hex(particle_file_named(o.source));
    inputs["particles"] = source;
    return inputs;
}

} // namespace sphkern::cli
