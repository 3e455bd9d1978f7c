#include "particles/slabs/slab_plan.hpp"

#include "particles/engine/periodic_images.hpp"
#include "particles/particle_statistics.hpp"
#include "particles/particles_memory.hpp"
#include "support/error.hpp"
#include "support/process/interruption.hpp"
#include "support/process/parallel_for.hpp"
#include "support/text/setting_names.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace sphkern {

namespace {

// A sum over the whole set taken run by run as parallel_sum takes it at once: each block of
// particle_block_size summed in order, the blocks added in block order. The same bits.
class BlockSum {
public:
    explicit BlockSum(std::size_t n) : blocks_((n + particle_block_size - 1) / particle_block_size, 0.0) {}
    template <class Term>
    void add(std::size_t begin, std::size_t count, int threads, const Term& term)
    {
        ParallelFor pass;
        pass.run_blocks(count, particle_block_size, threads, [&](std::size_t b, std::size_t from, std::size_t to) {
            double& sum = blocks_[begin / particle_block_size + b];
            for (std::size_t i = from; i < to; ++i) sum += term(i);
        });
    }
    double total() const
    {
        double total = 0;
        for (const double b : blocks_) total += b;
        return total;
    }

private:
    std::vector<double> blocks_;
};

} // namespace

std::size_t slab_run_rows(int threads, std::size_t row_bytes, std::size_t room)
{
    const std::size_t fit = room / std::max<std::size_t>(1, row_bytes * particle_block_size);
    // As many rows a thread as the percentiles' buckets, so that each thread counts a share of a run.
    const std::size_t per_thread = statistics_detail::buckets / particle_block_size;
    const std::size_t blocks =
        std::clamp<std::size_t>(fit, 2, per_thread * static_cast<std::size_t>(std::max(1, threads)));
    return blocks * particle_block_size;
}

ParticleSet read_valid_rows(const SnapshotRows& file, std::size_t begin, std::size_t end, int threads)
{
    throw_if_interrupted();
    ParticleSet rows = file.rows(begin, end);
    validate_particle_values(rows, threads);
    return rows;
}

namespace {

// Pass 1: the volumes, masses and file h, checked and summed as the whole set's; the plan's
// volume, h, h_max, mean volume, spacing and rho0.
void measure_rows(const SnapshotRows& file, const Kernel& kernel, const SlabPlanInputs& in, SlabPlan& plan)
{
    const ParticleSet& sample = file.sample();
    const std::size_t n = file.size();
    const int dim = sample.dimension, threads = in.threads;
    const bool file_h = in.smoothing.rule == SmoothingRule::file;
    BlockSum volume_sum(n), mass_sum(n);
    bool first = true;
    for (std::size_t begin = 0; begin < n; begin += in.run_rows) {
        const ParticleSet rows = read_valid_rows(file, begin, std::min(n, begin + in.run_rows), threads);
        const std::size_t count = rows.size();
        if (in.volume == VolumeModel::file) {
            const PerParticle v = particle_volumes(rows, in.volume, threads);
            if (const auto i =
                    first_index_where(count, threads, [&](std::size_t i) { return !std::isfinite(v[i]) || v[i] <= 0; }))
                fail_input(
                    fmt::format("volume of particle {} is {}, expected a positive finite number", rows.id(*i), v[*i]));
            if (first) plan.volume = v[0];
            plan.uniform_volume = plan.uniform_volume && !first_index_where(count, threads, [&](std::size_t i) {
                                      return v[i] != plan.volume;
                                  });
            volume_sum.add(begin, count, threads, [&](std::size_t i) { return v[i]; });
        } else {
            volume_sum.add(begin, count, threads, [&](std::size_t) { return plan.volume; });
        }
        if (!rows.mass.empty()) mass_sum.add(begin, count, threads, [&](std::size_t i) { return rows.mass[i]; });
        if (file_h) {
            const PerParticle h = smoothing_lengths(rows, kernel, in.smoothing, 0, threads);
            if (first) plan.h = h[0];
            plan.uniform_h =
                plan.uniform_h && !first_index_where(count, threads, [&](std::size_t i) { return h[i] != plan.h; });
            plan.h_max =
                std::max(plan.h_max, parallel_reduce(
                                         count, threads, 0.0, [&](std::size_t i, double& m) { m = std::max(m, h[i]); },
                                         [](double& m, double block) { m = std::max(m, block); }));
        }
        first = false;
    }
    const double total_volume = volume_sum.total();
    plan.mean_volume = total_volume / static_cast<double>(n);
    plan.spacing = std::pow(plan.mean_volume, 1.0 / dim);
    plan.rho0 = in.rho0.value_or(1.0);
    if (!in.rho0 && !sample.mass.empty()) plan.rho0 = mass_sum.total() / total_volume;
    if (!file_h)
        plan.h = plan.h_max = smoothing_lengths(sample, kernel, in.smoothing, plan.mean_volume, threads).uniform;
}

// Pass 2: the extent of the particles and their images, which sizes the whole set's bins
// (minima, maxima and a count: exact in any order, so each run is taken on the threads).
GridGeometry points_geometry(const SnapshotRows& file, const SlabPlanInputs& in,
                             const std::optional<PeriodicImages>& images, double reach)
{
    using Extent = std::array<double, 7>; // min and max along x, y, z, and the points
    const Extent none = {INFINITY, -INFINITY, INFINITY, -INFINITY, INFINITY, -INFINITY, 0};
    Extent extent = none;
    auto widen = [](Extent& e, const Extent& more) {
        for (int a = 0; a < 3; ++a)
            e[2 * a] = std::min(e[2 * a], more[2 * a]), e[2 * a + 1] = std::max(e[2 * a + 1], more[2 * a + 1]);
        e[6] += more[6];
    };
    const std::size_t n = file.size();
    for (std::size_t begin = 0; begin < n; begin += in.run_rows) {
        const ParticleSet rows = read_valid_rows(file, begin, std::min(n, begin + in.run_rows), in.threads);
        widen(extent, parallel_reduce(
                          rows.size(), in.threads, none,
                          [&](std::size_t i, Extent& e) {
                              for_each_point(rows, i, images, [&](double x, double y, double z) {
                                  widen(e, {x, x, y, y, z, z, 1});
                              });
                          },
                          widen));
    }
    return GridGeometry::of({extent[0], extent[1], extent[2], extent[3], extent[4], extent[5]},
                            static_cast<std::size_t>(extent[6]), reach);
}

// Pass 3: the points in each row of bins along the plan's axis (integers: each thread counts its own).
std::vector<std::size_t> points_per_row(const SnapshotRows& file, const SlabPlanInputs& in,
                                        const std::optional<PeriodicImages>& images, const SlabPlan& plan)
{
    const int axis = plan.axis, threads = in.threads;
    const std::size_t n = file.size();
    std::vector<std::size_t> in_row(plan.geometry.n[axis], 0);
    for (std::size_t begin = 0; begin < n; begin += in.run_rows) {
        const ParticleSet rows = read_valid_rows(file, begin, std::min(n, begin + in.run_rows), threads);
        std::vector<std::vector<std::size_t>> counts(static_cast<std::size_t>(std::max(1, threads)));
        ParallelFor pass;
        pass.run(rows.size(), threads, [&](int t, std::size_t from, std::size_t to) {
            auto& c = counts[static_cast<std::size_t>(t)];
            c.assign(in_row.size(), 0);
            for (std::size_t i = from; i < to; ++i)
                for_each_point(rows, i, images, [&](double x, double y, double z) {
                    const double at[3] = {x, y, z};
                    ++c[plan.geometry.bin(axis, at[axis])];
                });
        });
        for (const auto& c : counts)
            for (std::size_t r = 0; r < c.size(); ++r) in_row[r] += c[r];
    }
    return in_row;
}

// Slabs of whole rows, each as thick as the budget allows with its halo.
std::vector<Slab> cut_slabs(const std::vector<std::size_t>& in_row, std::size_t slab_bytes, const std::string& name)
{
    const std::size_t rows_along = in_row.size();
    auto points_in = [&](std::size_t own_first, std::size_t own_last) {
        Slab s{own_first > 0 ? own_first - 1 : 0, std::min(own_last + 1, rows_along), own_first, own_last, 0};
        for (std::size_t r = s.first; r < s.last; ++r) s.points += in_row[r];
        return s;
    };
    const std::size_t most = slab_bytes / bytes_per_particle;
    std::vector<Slab> slabs;
    for (std::size_t a = 0; a < rows_along;) {
        Slab slab = points_in(a, a + 1);
        if (slab.points > most)
            fail_input(
                fmt::format("{}: a slab one row of bins thick holds {} particles and images ({:.4g} bytes), over the "
                            "{:.4g} bytes a slab may take of the memory budget of {:.4g} bytes ({}); expected a "
                            "larger budget",
                            name, slab.points, static_cast<double>(slab.points * bytes_per_particle),
                            static_cast<double>(most * bytes_per_particle), static_cast<double>(memory_limit_bytes()),
                            setting_named("memory_limit")));
        for (std::size_t b = a + 2; b <= rows_along; ++b) {
            const Slab thicker = points_in(a, b);
            if (thicker.points > most) break;
            slab = thicker;
        }
        slabs.push_back(slab);
        a = slab.own_last;
    }
    return slabs;
}

} // namespace

SlabPlan plan_slabs(const SnapshotRows& file, const Kernel& kernel, const SlabPlanInputs& in, std::size_t slab_bytes)
{
    const ParticleSet& sample = file.sample();
    const int dim = sample.dimension;
    SlabPlan plan;
    plan.particles = file.size();
    plan.axis = dim - 1;
    if (in.volume == VolumeModel::uniform) {
        if (!sample.box) particle_volumes(sample, in.volume); // the refusal of a set without a box
        plan.volume = sample.box->volume(dim) / static_cast<double>(plan.particles); // mean_volume of the whole set
    }
    measure_rows(file, kernel, in, plan);
    const double reach = kernel.support() * plan.h_max;
    if (sample.box && sample.box->smallest_width(dim) < 2 * reach)
        fail_input(
            fmt::format("{}: the periodic box is {:.6g} wide, less than twice the support radius {:.6g}; expected a "
                        "larger box or a smaller h",
                        sample.name, sample.box->smallest_width(dim), reach));
    const auto images = periodic_images_of(sample, reach);
    plan.geometry = points_geometry(file, in, images, reach);
    plan.slabs = cut_slabs(points_per_row(file, in, images, plan), slab_bytes, sample.name);
    return plan;
}

} // namespace sphkern
