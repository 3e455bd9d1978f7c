#include "requests/source_request.hpp"

#include "lattices/lattice.hpp"
#include "particles/formats/particle_arrays.hpp"
#include "particles/particles_memory.hpp"
#include "support/error.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>

namespace sphkern {

SourceSources source_sources(FrontEnd f)
{
    auto n = [f](const char* key) { return value_named(f, key); };
    return {n("size"),
            n("sigma"),
            n("count"),
            n("dim"),
            n("box"),
            n("array"),
            n("particle_radius"),
            n("cell"),
            f == FrontEnd::command_line ? "--memory-limit" : ""};
}

namespace {

// The settings of a file source: its arrays, dimension, box and particle radius.
void file_source(const SourceArguments& o, const SourceSources& sources, ParticleSource& source)
{
    source.file.array = o.array;
    source.file.particle_radius = o.particle_radius;
    if (o.dim) source.file.dimension = o.dim;
    if (!o.box.empty()) {
        const auto sides = parse_number_list(o.box, sources.box, 2, 3);
        source.box = Eigen::Vector3d(sides[0], sides[1], sides.size() == 3 ? sides[2] : 1.0);
    }
}

// The setting's name, then the problem ("--size cuts a lattice into a block; ...").
[[noreturn]] void refuse(const ValueSource& setting, const std::string& problem, ErrorKind kind = ErrorKind::general)
{
    throw Error(setting.code, setting.name + problem, kind);
}

} // namespace

ParticleSource particle_source_of(const SourceArguments& o, const SourceSources& sources)
{
    ParticleSource source;
    source.spec = o.spec;
    source.kind = source_kind(o.spec);
    auto names = shipped_lattice_names();
    if (source.kind == SourceKind::lattice && !o.spec.ends_with(".json") &&
        std::find(names.begin(), names.end(), o.spec) == names.end()) {
        names.push_back("poisson");
        fail_unknown(fmt::format("unknown source \"{}\"{}; expected poisson, a lattice ({}) or a particle file", o.spec,
                                 did_you_mean(o.spec, names), fmt::join(names.begin(), names.end() - 1, ", ")));
    }
    if (source.kind != SourceKind::lattice && !o.size.empty())
        refuse(sources.size, " cuts a lattice into a block; " + o.spec + " is not a lattice");
    if (source.kind != SourceKind::lattice && !o.cell.empty())
        refuse(sources.cell, " is the cell of a lattice block; " + o.spec + " is not a lattice");
    if (!o.cell.empty() && o.cell != "primitive" && o.cell != "rectangular")
        refuse(sources.cell, ": \"" + o.cell + "\" is unknown, expected primitive or rectangular",
               ErrorKind::unknown_name);
    source.block.rectangular = o.cell == "rectangular";
    if (source.kind != SourceKind::poisson && o.count) refuse(sources.count, " is for poisson sets");
    if (source.kind == SourceKind::lattice) {
        if (o.size.empty())
            throw Error(sources.size.code,
                        "a lattice source needs " + sources.size.name + " N1,N2[,N3] (cells of the periodic block)");
        const auto cells = parse_number_list(o.size, sources.size, 2, 3);
        for (std::size_t a = 0; a < cells.size(); ++a) {
            if (cells[a] != std::floor(cells[a]) || std::abs(cells[a]) > 1e15)
                refuse(sources.size, " " + o.size + ": expected whole numbers of cells");
            source.block.cells[a] = static_cast<long long>(cells[a]);
        }
        source.cell_counts = cells.size();
        source.block.sigma = o.sigma;
        source.block.seed = o.seed;
    } else if (o.sigma != 0) {
        refuse(sources.sigma, " disturbs a lattice; " + o.spec + " is not a lattice");
    }
    if (source.kind == SourceKind::poisson) {
        if (!o.count) throw Error(sources.count.code, "a poisson set needs " + sources.count.name + " N");
        source.poisson.count = static_cast<std::size_t>(o.count);
        source.poisson.dimension = o.dim ? o.dim : 3;
        source.poisson.seed = o.seed;
        if (!o.box.empty()) {
            const auto sides = parse_number_list(o.box, sources.box, 1, 3);
            for (int a = 0; a < 3; ++a)
                source.poisson.box[a] =
                    sides[sides.size() == 1 ? 0 : std::min<std::size_t>(static_cast<std::size_t>(a), sides.size() - 1)];
            if (sides.size() != 1 && static_cast<int>(sides.size()) != source.poisson.dimension)
                refuse(sources.box, " " + o.box + ": give one side or one per dimension");
        }
    }
    if (source.kind == SourceKind::file) file_source(o, sources, source);
    else if (!o.array.empty()) refuse(sources.array, " chooses a PySPH particle array; " + o.spec + " is not a file");
    else if (o.particle_radius)
        refuse(sources.particle_radius, " gives the h of a SPlisHSPlasH file; " + o.spec + " is not a file");
    return source;
}

namespace {

void check_box(const Eigen::Vector3d& sides, int dimension, const ValueSource& source)
{
    for (int a = 0; a < dimension; ++a)
        if (!std::isfinite(sides[a]) || sides[a] <= 0)
            source.fail(fmt::format("side {} is {}; expected a positive number", a + 1, sides[a]));
}

} // namespace

void check_particle_source(const ParticleSource& s, const SourceSources& sources)
{
    switch (s.kind) {
    case SourceKind::lattice:
        for (const long long cells : s.block.cells) check_range(static_cast<double>(cells), 1, 1e6, sources.size);
        check_number(s.block.sigma, 0, 10, LowEnd::closed, sources.sigma, " (units of d)");
        return;
    case SourceKind::poisson:
        if (s.poisson.dimension != 2 && s.poisson.dimension != 3)
            sources.dim.fail(fmt::format("{}: expected 2 or 3", s.poisson.dimension));
        check_range(static_cast<double>(s.poisson.count), 2, 0x1p40, sources.count);
        return check_box(s.poisson.box, s.poisson.dimension, sources.box);
    case SourceKind::file:
        if (s.file.dimension && *s.file.dimension != 2 && *s.file.dimension != 3)
            sources.dim.fail(fmt::format("{}: expected 2 or 3", *s.file.dimension));
        if (s.box) check_box(*s.box, 3, sources.box);
        if (const std::string problem = particle_array_list_problem(s.file.array); !problem.empty())
            throw Error(sources.array.code, sources.array.name + " " + s.file.array + ": " + problem);
        // Its support radius, 4 r (SPlisHSPlasH's), must be a finite length too.
        if (s.file.particle_radius && !(*s.file.particle_radius > 0 && std::isfinite(4 * *s.file.particle_radius)))
            throw Error(sources.particle_radius.code,
                        fmt::format("{}: expected a positive length whose support radius 4 r is finite",
                                    sources.particle_radius.about(*s.file.particle_radius)));
    }
}

void set_memory_budget(double gib, const ValueSource& source)
{
    if (!std::isfinite(gib) || gib < 0 || gib > max_memory_limit_gib)
        throw Error(source.code,
                    fmt::format("{}: expected GiB in [0, 1e6] (0: from the available memory)", source.about(gib)));
    // A positive budget below one byte would be taken as 0, "from the available memory": the opposite of what was
    // asked.
    if (gib > 0 && gib * 1073741824.0 < 1)
        throw Error(source.code,
                    fmt::format("{}: less than one byte; expected 0 (from the available memory) or at least "
                                "1e-9 GiB",
                                source.about(gib)));
    set_memory_limit_gib(gib);
}

ParticleSet load_source(const ParticleSource& s, const SourceSources& sources, int threads)
{
    check_particle_source(s, sources);
    threads = worker_threads(threads);
    const std::size_t budget = max_particles();
    auto over_budget = [&](const ValueSource& source, double count) {
        if (count > static_cast<double>(budget)) // a request over a limit: input, whatever the source
            fail_input(fmt::format("{}: {:.0f} particles, more than the memory limit of {} particles{}", source.name,
                                   count, budget, sources.budget.empty() ? "" : " (" + sources.budget + ")"));
    };
    if (s.kind == SourceKind::lattice) {
        const Lattice lattice = block_cell(load_lattice(s.spec), s.block);
        if (s.cell_counts != static_cast<std::size_t>(lattice.dimension))
            throw Error(ExitCode::input, fmt::format("{}: the lattice is {}D, expected {} cell counts",
                                                     sources.size.name, lattice.dimension, lattice.dimension));
        double count = lattice.sites();
        for (const long long cells : s.block.cells) count *= static_cast<double>(cells);
        over_budget(sources.size, count);
        return lattice_particles(lattice, s.block, threads);
    }
    if (s.kind == SourceKind::poisson) {
        over_budget(sources.count, static_cast<double>(s.poisson.count));
        return poisson_particles(s.poisson, threads);
    }
    return load_particles(s, threads);
}

std::unique_ptr<SnapshotRows> snapshot_in_slabs(const ParticleSource& s, const SourceSources& sources)
{
    if (s.kind != SourceKind::file || particle_file_format(s.spec) != ParticleFileFormat::hdf5) return nullptr;
    check_particle_source(s, sources);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(s.spec, ec) || !is_snapshot(s.spec)) return nullptr;
    auto snapshot = std::make_unique<SnapshotRows>(s.spec);
    if (snapshot->size() <= max_particles()) return nullptr;
    if (s.file.dimension)
        sources.dim.fail(
            fmt::format("{}: a snapshot of {} particles, over the memory budget, is read in slabs; expected its "
                        "/Header Dimension instead",
                        *s.file.dimension, snapshot->size()));
    if (s.box) {
        PeriodicBox box;
        for (int a = 0; a < snapshot->sample().dimension; ++a) box.edges(a, a) = (*s.box)[a];
        snapshot->set_box(box);
    }
    return snapshot;
}

} // namespace sphkern
