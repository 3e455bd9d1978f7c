#include "particles/slabs/particles_in_slabs.hpp"

#include "particles/engine/periodic_images.hpp"
#include "particles/particle_measures.hpp"
#include "particles/particles_memory.hpp"
#include "particles/slabs/slab_plan.hpp"
#include "particles/slabs/slab_spills.hpp"
#include "support/error.hpp"
#include "support/process/parallel_for.hpp"
#include "support/process/progress.hpp"
#include "support/text/setting_names.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>

namespace sphkern {

namespace {

// A spilled record: the particle's row, h and the statistics' measures; then, for a
// per-particle output, its position, volume, e1 and m1.
enum Field : std::size_t {
    row,
    h_field,
    neighbours,
    e0,
    eps_rho,
    eps_gradp,
    eps_gradp_sum,
    e1_norm,
    m1_norm,
    E_norm,
    x,
    y,
    z,
    volume,
    e1,
    m1 = e1 + 3
};
constexpr std::size_t statistics_fields = E_norm + 1, output_fields = m1 + 3;
// The column of each of measure_names.
constexpr Field measure_field[] = {e0, eps_rho, eps_gradp, eps_gradp_sum, e1_norm, m1_norm, E_norm, neighbours};

// A particle in a slab's input: its row, position, and its h, mass and density where the file has them.
struct InputLayout {
    bool h, mass, density;
    std::size_t fields() const { return 4 + h + mass + density; }
};

// One pass over the file: each particle to the input of every slab that holds a point of it
// (itself or a periodic image), in file order. A run's blocks are sorted on the threads, each
// into records per slab, and appended block after block.
void distribute(const SnapshotRows& file, const SlabPlan& plan, double reach, const InputLayout& layout,
                SlabSpills& inputs, std::size_t run, int threads)
{
    const auto images = periodic_images_of(file.sample(), reach);
    // The slabs a row of bins belongs to: its own slab, and the one or two whose halo it is.
    std::vector<std::array<std::size_t, 3>> slabs_of(plan.geometry.n[plan.axis], {SIZE_MAX, SIZE_MAX, SIZE_MAX});
    for (std::size_t s = 0; s < plan.slabs.size(); ++s)
        for (std::size_t r = plan.slabs[s].first; r < plan.slabs[s].last; ++r)
            *std::find(slabs_of[r].begin(), slabs_of[r].end(), SIZE_MAX) = s;
    // Each block's records per slab, kept from run to run (their room is taken once).
    std::vector<std::vector<std::vector<double>>> blocks((run + particle_block_size - 1) / particle_block_size,
                                                         std::vector<std::vector<double>>(plan.slabs.size()));
    for (std::size_t begin = 0; begin < file.size(); begin += run) {
        const ParticleSet rows = read_valid_rows(file, begin, std::min(file.size(), begin + run), threads);
        ParallelFor pass;
        pass.run_blocks(
            rows.size(), particle_block_size, threads, [&](std::size_t b, std::size_t from, std::size_t end) {
                auto& records = blocks[b];
                for (auto& r : records) r.clear();
                for (std::size_t i = from; i < end; ++i) {
                    std::array<std::size_t, 6>
                        to; // its points lie in two rows at most (z and an image's), each in three slabs at most
                    std::size_t count = 0;
                    auto add = [&](double x, double y, double z) {
                        const double c[3] = {x, y, z};
                        for (const std::size_t s : slabs_of[plan.geometry.bin(plan.axis, c[plan.axis])])
                            if (s != SIZE_MAX && std::find(to.begin(), to.begin() + static_cast<std::ptrdiff_t>(count),
                                                           s) == to.begin() + static_cast<std::ptrdiff_t>(count))
                                to[count++] = s;
                    };
                    for_each_point(rows, i, images, add);
                    for (std::size_t k = 0; k < count; ++k) {
                        auto& r = records[to[k]];
                        r.insert(r.end(), {static_cast<double>(rows.id(i)), rows.x[i], rows.y[i], rows.z[i]});
                        if (layout.h) r.push_back(rows.h[i]);
                        if (layout.mass) r.push_back(rows.mass[i]);
                        if (layout.density) r.push_back(rows.density[i]);
                    }
                }
            });
        for (std::size_t b = 0; b * particle_block_size < rows.size(); ++b)
            for (std::size_t s = 0; s < blocks[b].size(); ++s)
                if (!blocks[b][s].empty()) inputs.append(s, blocks[b][s]);
    }
    for (std::size_t s = 0; s < plan.slabs.size(); ++s) inputs.close_slab(s);
}

// Slab s's particles from its input, in file order.
ParticleSet read_slab(const ParticleSet& sample, const SlabSpills& inputs, std::size_t s, const InputLayout& layout,
                      std::size_t points)
{
    ParticleSet set = sample;
    for (auto* v : {&set.x, &set.y, &set.z, &set.h, &set.mass, &set.density}) v->clear(), v->reserve(points);
    set.linked_files.clear();
    set.ids.reserve(points);
    inputs.read(s, [&](const double* r) {
        set.ids.push_back(static_cast<std::uint64_t>(r[0]));
        set.x.push_back(r[1]), set.y.push_back(r[2]), set.z.push_back(r[3]);
        std::size_t k = 4;
        if (layout.h) set.h.push_back(r[k++]);
        if (layout.mass) set.mass.push_back(r[k++]);
        if (layout.density) set.density.push_back(r[k++]);
    });
    return set;
}

// The records of a slab's own particles (those in its own rows), in file order: formatted in
// blocks on the threads, a run of particles at a time, and handed to `append` block after
// block. `alone` becomes the lowest row of a particle with no neighbour, and its h.
void spill_own_particles(const ParticleSet& set, const ParticleMeasures& m, const PerParticle& h,
                         const PerParticle& volumes, const SlabPlan& plan, const Slab& slab, bool per_particle,
                         std::size_t run, int threads, std::optional<std::pair<std::uint64_t, double>>& alone,
                         const std::function<void(std::span<const double>)>& append)
{
    const auto lower = [](auto& a, const auto& b) {
        if (b && (!a || b->first < a->first)) a = b;
    };
    // Each block's records, kept from run to run (their room is taken once).
    std::vector<std::vector<double>> records((run + particle_block_size - 1) / particle_block_size);
    for (std::size_t first = 0; first < set.measured(); first += run) {
        const std::size_t count = std::min(run, set.measured() - first);
        const std::size_t blocks = (count + particle_block_size - 1) / particle_block_size;
        std::vector<std::optional<std::pair<std::uint64_t, double>>> alone_in(blocks);
        ParallelFor pass;
        pass.run_blocks(count, particle_block_size, threads, [&](std::size_t b, std::size_t from, std::size_t end) {
            records[b].clear();
            for (std::size_t i = first + from; i < first + end; ++i) {
                const double c[3] = {set.x[i], set.y[i], set.z[i]};
                const std::size_t r = plan.geometry.bin(plan.axis, c[plan.axis]);
                if (r < slab.own_first || r >= slab.own_last) continue;
                const MeasureRecord& s = m.scalars[i];
                if (s.neighbours == 0) lower(alone_in[b], std::optional(std::pair(set.ids[i], h[i])));
                const double record[] = {static_cast<double>(set.ids[i]),
                                         h[i],
                                         static_cast<double>(s.neighbours),
                                         s.e0,
                                         m.eps_rho_of(i),
                                         s.eps_gradp,
                                         s.eps_gradp_sum,
                                         s.e1_norm,
                                         s.m1_norm,
                                         s.E_norm};
                records[b].insert(records[b].end(), std::begin(record), std::end(record));
                if (per_particle) {
                    const double more[] = {set.x[i],   set.y[i],   set.z[i],   volumes[i], m.e1[i][0],
                                           m.e1[i][1], m.e1[i][2], m.m1[i][0], m.m1[i][1], m.m1[i][2]};
                    records[b].insert(records[b].end(), std::begin(more), std::end(more));
                }
            }
        });
        for (std::size_t b = 0; b < blocks; ++b) append(records[b]), lower(alone, alone_in[b]);
    }
}

// The sample holds the header, not the count: the file's count is given.
void refuse(const ParticleSet& sample, std::size_t particles, const std::string& what)
{
    fail_input(fmt::format("{}: {} particles, over the memory budget ({}), are measured in slabs, which {}",
                           sample.name, particles, setting_named("memory_limit"), what));
}

// What a set measured slab by slab cannot take.
void refuse_what_slabs_cannot(const ParticleSet& sample, std::size_t n, const ParticleRequest& request,
                              VolumeModel model)
{
    if (request.sweep) refuse(sample, n, "take one h, not a sweep");
    if (request.smoothing.rule == SmoothingRule::density)
        refuse(sample, n, "take h from h over l, N_H or the file, not solved from each particle's density");
    if (model == VolumeModel::voronoi) refuse(sample, n, "take uniform volumes or the file's, not Voronoi cells");
    if (!request.given_volumes.empty()) refuse(sample, n, "take uniform volumes or the file's, not given ones");
}

// The statistics (and histograms) of the spills merged into file order, in three passes
// (ExactSummary); the per-particle output to `rows` with the first. Returns h's moments.
Summary summarise_spills(SlabSpills& spills, std::size_t n, std::size_t run, int threads, std::size_t histogram_bins,
                         const MeasuredRowsSink& rows, ParticlePoint& point)
{
    const bool per_particle = static_cast<bool>(rows);
    const std::size_t measures = std::size(measure_names);
    std::vector<ExactSummary> summaries(measures + 1, ExactSummary(n)); // and h's
    spills.merge(n, run, threads, [&](std::size_t begin, std::size_t count, const std::vector<std::vector<double>>& c) {
        for (std::size_t f = 0; f < measures; ++f)
            summaries[f].add_moments(begin, count, threads, [&](std::size_t k) { return c[measure_field[f]][k]; });
        summaries[measures].add_moments(begin, count, threads, [&](std::size_t k) { return c[h_field][k]; });
        if (!per_particle) return;
        rows({begin,
              count,
              c[x].data(),
              c[y].data(),
              c[z].data(),
              c[h_field].data(),
              c[volume].data(),
              c[neighbours].data(),
              c[e0].data(),
              c[eps_rho].data(),
              c[eps_gradp].data(),
              {c[e1].data(), c[e1 + 1].data(), c[e1 + 2].data()},
              {c[m1].data(), c[m1 + 1].data(), c[m1 + 2].data()}});
    });
    std::vector<Histogram> histograms;
    for (std::size_t f = 0; histogram_bins && f < measures_with_histograms; ++f) {
        const Summary s = summaries[f].moments();
        histograms.emplace_back(s.min, s.max, histogram_bins);
    }
    spills.merge(n, run, threads, [&](std::size_t, std::size_t count, const std::vector<std::vector<double>>& c) {
        for (std::size_t f = 0; f < measures; ++f)
            summaries[f].count(count, threads, [&](std::size_t k) { return c[measure_field[f]][k]; });
        for (std::size_t f = 0; f < histograms.size(); ++f)
            histograms[f].add({c[measure_field[f]].data(), count}, threads);
    });
    spills.merge(n, run, threads, [&](std::size_t, std::size_t count, const std::vector<std::vector<double>>& c) {
        for (std::size_t f = 0; f < measures; ++f)
            summaries[f].gather(count, threads, [&](std::size_t k) { return c[measure_field[f]][k]; });
    });
    for (std::size_t f = 0; f < measures; ++f) point.statistics.emplace_back(measure_names[f], summaries[f].finish());
    for (std::size_t f = 0; f < histograms.size(); ++f) point.histograms.emplace_back(measure_names[f], histograms[f]);
    return summaries[measures].moments();
}

// The rows read (and records spilled) at once: beside a slab, a run of rows read and of records
// spilled are held; after the slabs, the merge and the statistics hold a run of records, each
// slab's read buffer, the blocks' moments and the percentiles' buckets (about 8 MiB).
std::size_t rows_read_at_once(const std::string& name, std::size_t n, int threads, std::size_t fields)
{
    const std::size_t row_bytes = (8 + fields) * sizeof(double);
    const std::size_t run = slab_run_rows(threads, row_bytes, memory_limit_bytes() / 4);
    const std::size_t beside_slab = run * row_bytes;
    const std::size_t statistics = (std::size_t{8} << 20) + (n / particle_block_size + 1) * 400;
    if (memory_limit_bytes() <= std::max(beside_slab, statistics))
        fail_input(fmt::format(
            "{}: the memory budget of {:.4g} bytes ({}) leaves nothing for a slab; expected more than {:.4g}", name,
            static_cast<double>(memory_limit_bytes()), setting_named("memory_limit"),
            static_cast<double>(std::max(beside_slab, statistics))));
    return run;
}

// What every slab's measure takes alike.
struct SlabRun {
    const ParticleSet& sample;
    SlabSpills& inputs;
    InputLayout layout;
    const ParticleRequest& request;
    VolumeModel model;
    std::size_t run;
    int threads;
    bool per_particle;
};

// Each slab read, measured and its own particles' records spilled, in turn. Refuses a set where
// a particle sees no other: it has no SPH sums to judge, h is too small for the set.
void measure_slabs(const Kernel& kernel, const SlabPlan& plan, const SlabRun& r, SlabSpills& spills,
                   ParticleAnswer& answer, ParticlePoint& point)
{
    PhaseTimes& phases = answer.phases;
    const SmoothingSpec& spec = r.request.smoothing;
    const int threads = r.threads;
    std::optional<std::pair<std::uint64_t, double>> alone; // the first particle with no neighbour, and its h
    Progress progress(r.sample.name + ": slabs", plan.slabs.size());
    for (std::size_t s = 0; s < plan.slabs.size(); ++s) {
        const Slab& slab = plan.slabs[s];
        progress.reach(s, fmt::format("slab {} of {}", s + 1, plan.slabs.size()));
        phases.restart();
        const ParticleSet set = read_slab(r.sample, r.inputs, s, r.layout, slab.points);
        const PerParticle volumes =
            plan.uniform_volume ? PerParticle::same(set.size(), plan.volume) : particle_volumes(set, r.model, threads);
        const PerParticle h = plan.uniform_h ? PerParticle::same(set.size(), plan.h)
                                             : smoothing_lengths(set, kernel, spec, plan.mean_volume, threads);
        phases.lap("read");
        const MeasureSlab window{{plan.geometry, plan.axis, slab.first, slab.last, slab.own_first, slab.own_last},
                                 plan.h_max};
        const MeasureInputs inputs{h.view(),       volumes.view(),  set.mass,       plan.rho0,
                                   plan.spacing,   r.request.depth, answer.gravity, r.request.threads,
                                   r.per_particle, spec.pair,       &window};
        const ParticleMeasures m = measure_particles(kernel, set, inputs);
        phases.merge(m.phases);
        phases.restart();
        point.seconds += m.seconds, point.cpu_seconds += m.cpu_seconds, point.pairs += m.pairs;
        spill_own_particles(set, m, h, volumes, plan, slab, r.per_particle, r.run, threads, alone,
                            [&](std::span<const double> records) { spills.append(s, records); });
        spills.close_slab(s);
        phases.lap("spill");
    }
    if (alone)
        fail_input(
            fmt::format("{}: particle {} has no neighbour inside its support (h = {:.6g}); expected a larger h or a "
                        "denser set",
                        r.sample.name, alone->first, alone->second));
}

} // namespace

std::size_t slab_spill_bytes(std::size_t particles, bool per_particle)
{
    return particles * (per_particle ? output_fields : statistics_fields) * sizeof(double);
}

ParticleAnswer analyse_particles_in_slabs(const Kernel& kernel, const SnapshotRows& file,
                                          const ParticleRequest& request, const MeasuredRowsSink& rows)
{
    const ParticleSet& sample = file.sample();
    const std::size_t n = file.size();
    kernel.require_dimension(sample.dimension, sample.name);
    if (n < 2) fail_input(fmt::format("{}: {} particles; expected at least 2", sample.name, n));
    const SmoothingSpec& spec = request.smoothing;
    const VolumeModel model = request.volume.value_or(default_volume_model(sample));
    refuse_what_slabs_cannot(sample, n, request, model);
    const bool per_particle = static_cast<bool>(rows);
    const std::size_t fields = per_particle ? output_fields : statistics_fields;
    // The disk the slabs' files need: their results before anything is read, their inputs too once planned.
    const auto room = std::filesystem::space(SlabSpills::folder_parent()).available;
    auto require_room = [&](std::size_t bytes, const char* what) {
        if (bytes > room)
            fail_input(
                fmt::format("{}: the slabs' {} need {:.4g} bytes of disk in {}, which has {:.4g}; expected more room "
                            "there (TMPDIR)",
                            sample.name, what, static_cast<double>(bytes), SlabSpills::folder_parent().string(),
                            static_cast<double>(room)));
    };
    require_room(slab_spill_bytes(n, per_particle), "per-particle results");
    ParticleAnswer answer;
    PhaseTimes& phases = answer.phases;
    const int threads = worker_threads(request.threads);
    answer.particles = n, answer.volume = model, answer.threads = threads;
    answer.gravity = request.gravity ? request.gravity->normalized() : sample.gravity;

    const std::size_t run = rows_read_at_once(sample.name, n, threads, fields);
    const std::size_t beside_slab = run * (8 + fields) * sizeof(double);
    const SlabPlan plan =
        plan_slabs(file, kernel, {spec, model, request.rho0, threads, run}, memory_limit_bytes() - beside_slab);
    answer.mean_volume = plan.mean_volume, answer.rho0 = plan.rho0, answer.spacing = plan.spacing;
    spdlog::debug("{}: {} particles in {} slabs along axis {}, read in runs of {} rows", sample.name, n,
                  plan.slabs.size(), plan.axis, run);

    // The slabs' inputs, written in one more pass, and the room they and the results take.
    const InputLayout layout{!sample.h.empty(), !sample.mass.empty(), !sample.density.empty()};
    std::size_t slab_points = 0;
    for (const Slab& slab : plan.slabs) slab_points += slab.points;
    require_room(slab_points * layout.fields() * sizeof(double) + slab_spill_bytes(n, per_particle),
                 "inputs and results");
    const double reach = kernel.support() * plan.h_max;
    SlabSpills inputs(layout.fields(), plan.slabs.size());
    distribute(file, plan, reach, layout, inputs, run, threads);
    phases.lap("plan");
    SlabSpills spills(fields, plan.slabs.size());
    ParticlePoint point;
    measure_slabs(kernel, plan, {sample, inputs, layout, request, model, run, threads, per_particle}, spills, answer,
                  point);
    const Summary h_moments = summarise_spills(spills, n, run, threads, request.histogram_bins, rows, point);
    point.mean_neighbours = point.statistics.back().second.mean;
    finish_point(point, h_moments, std::pow(plan.mean_volume, 1.0 / sample.dimension), kernel.support(), sample,
                 plan.rho0);
    phases.lap("statistics");
    answer.points.push_back(std::move(point));
    return answer;
}

} // namespace sphkern
