#include "requests/source_request.hpp"

#include "particles/formats/particle_arrays.hpp"
#include "particles/particles_memory.hpp"
#include "support/error.hpp"

#include <fmt/format.h>

#include <cmath>

namespace sphkern {

SourceSources source_sources(FrontEnd f)
{
    auto n = [f](const char* key) { return value_named(f, key); };
    return {n("size"), n("sigma"), n("count"), n("dim"), n("box"), n("array"), n("particle_radius"),
            f == FrontEnd::command_line ? "--memory-limit" : ""};
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
        if (s.poisson.dimension != 2 && s.poisson.dimension != 3) sources.dim.fail(fmt::format("{}: expected 2 or 3", s.poisson.dimension));
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
        throw Error(source.code, fmt::format("{}: expected GiB in [0, 1e6] (0: from the available memory)", source.about(gib)));
    // A positive budget below one byte would be taken as 0, "from the available memory": the opposite of what was asked.
    if (gib > 0 && gib * 1073741824.0 < 1)
        throw Error(source.code, fmt::format("{}: less than one byte; expected 0 (from the available memory) or at least "
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
            fail_input(fmt::format("{}: {:.0f} particles, more than the memory limit of {} particles{}", source.name, count,
                                   budget, sources.budget.empty() ? "" : " (" + sources.budget + ")"));
    };
    if (s.kind == SourceKind::lattice) {
        const Lattice lattice = block_cell(load_lattice(s.spec), s.block);
        if (s.cell_counts != static_cast<std::size_t>(lattice.dimension))
            throw Error(ExitCode::input, fmt::format("{}: the lattice is {}D, expected {} cell counts", sources.size.name,
                                                     lattice.dimension, lattice.dimension));
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
        sources.dim.fail(fmt::format("{}: a snapshot of {} particles, over the memory budget, is read in slabs; expected its "
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
