#include "particles/particle_analysis.hpp"

#include "support/error.hpp"
#include "support/process/first_touch.hpp"
#include "support/process/parallel_for.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <numeric>
#include <stdexcept>

namespace sphkern {

namespace {

// The measures' records read a run at a time into a column per measure: each pass of the
// statistics reads the records once (the passes read each value of a column); a run gives each
// thread a share of the percentiles' buckets to count, and is at most a quarter of the set, so
// that the columns take at most 16 bytes a particle (whole blocks: the moments go block by block).
class RecordColumns {
public:
    explicit RecordColumns(const ParticleMeasures& m) : m_(m), columns_(std::size(measure_names))
    {
        const std::size_t n = m.size(), quarter = n / 4 / particle_block_size * particle_block_size;
        run_ =
            std::max(particle_block_size,
                     std::min(statistics_detail::buckets * static_cast<std::size_t>(std::max(1, m.threads)), quarter));
        for (auto& column : columns_) column.resize(std::min(run_, n));
    }

    // Without masses eps_rho is e0: its summary is e0's (measure f's statistics are own(f)'s).
    std::size_t own(std::size_t f) const { return f == 1 && m_.eps_rho.empty() ? std::size_t{0} : f; }

    // step(f, begin, count, value) for each measure f that is its own, run by run; value(k) is
    // the k-th record's of the run.
    template <class Step>
    void each_run(const Step& step)
    {
        static constexpr double MeasureRecord::*fields[] = {&MeasureRecord::e0,        &MeasureRecord::e0,
                                                            &MeasureRecord::eps_gradp, &MeasureRecord::eps_gradp_sum,
                                                            &MeasureRecord::e1_norm,   &MeasureRecord::m1_norm,
                                                            &MeasureRecord::E_norm};
        const std::size_t n = m_.size();
        for (std::size_t begin = 0; begin < n; begin += run_) {
            const std::size_t count = std::min(run_, n - begin);
            ParallelFor pass;
            pass.run_blocks(count, particle_block_size, m_.threads, [&](std::size_t, std::size_t from, std::size_t to) {
                for (std::size_t k = from; k < to; ++k) {
                    const MeasureRecord& r = m_.scalars[begin + k];
                    for (std::size_t f = 0; f < 7; ++f) columns_[f][k] = r.*fields[f];
                    columns_[7][k] = r.neighbours;
                    if (!m_.eps_rho.empty()) columns_[1][k] = m_.eps_rho[begin + k];
                }
            });
            for (std::size_t f = 0; f < columns_.size(); ++f) {
                if (own(f) != f) continue;
                const double* column = columns_[f].data();
                step(f, begin, count, [column](std::size_t k) { return column[k]; });
            }
        }
    }

private:
    const ParticleMeasures& m_;
    std::size_t run_ = 0;
    std::vector<ParticleValues> columns_;
};

ParticlePoint summarise_point(const ParticleMeasures& m, std::size_t bins)
{
    const int threads = m.threads;
    const std::size_t n = m.size(), measures = std::size(measure_names);
    RecordColumns records(m);
    const auto own = [&](std::size_t f) { return records.own(f); };
    const auto each_run = [&](const auto& step) { records.each_run(step); };
    std::vector<ExactSummary> summaries(measures, ExactSummary(n));
    each_run([&](std::size_t f, std::size_t begin, std::size_t count, const auto& value) {
        summaries[f].add_moments(begin, count, threads, value);
    });
    std::vector<Histogram> histograms;
    for (std::size_t f = 0; bins && f < measures_with_histograms; ++f) {
        const Summary s = summaries[own(f)].moments();
        histograms.emplace_back(s.min, s.max, bins);
    }
    each_run([&](std::size_t f, std::size_t, std::size_t count, const auto& value) {
        summaries[f].count(count, threads, value);
        if (f < histograms.size()) histograms[f].add_values(count, threads, value);
    });
    each_run([&](std::size_t f, std::size_t, std::size_t count, const auto& value) {
        summaries[f].gather(count, threads, value);
    });
    ParticlePoint point;
    for (std::size_t f = 0; f < measures; ++f)
        point.statistics.emplace_back(measure_names[f], summaries[own(f)].finish());
    for (std::size_t f = 0; f < histograms.size(); ++f)
        point.histograms.emplace_back(measure_names[f], histograms[own(f)]);
    point.mean_neighbours = point.statistics.back().second.mean;
    point.seconds = m.seconds;
    point.cpu_seconds = m.cpu_seconds;
    point.pairs = m.pairs;
    return point;
}

// No result is printed as a non-finite number: statistics that overflow a double (eps_rho
// against a reference density far below the masses' density) are refused, naming the quantity.
void require_finite(const ParticlePoint& point, const ParticleSet& set, double rho0)
{
    for (const auto& [name, s] : point.statistics) {
        const double fields[] = {s.mean, s.std, s.rms, s.min, s.max, s.p1, s.p50, s.p99};
        if (std::all_of(std::begin(fields), std::end(fields), [](double v) { return std::isfinite(v); })) continue;
        const std::string why = name == std::string("eps_rho") && !set.mass.empty()
                                    ? fmt::format(" (the masses over rho0 = {:g}); expected a reference density "
                                                  "rho0 nearer the set's mass density",
                                                  rho0)
                                    : "; expected values within the range of a double";
        fail_input(fmt::format("{}: the statistics of {} overflow a double{}", set.name, name, why));
    }
}

// The volumes, their mean, the spacing and rho0 of the answer. The mean volume and rho0 are
// the measured particles' (a PySPH file's first array).
void answer_volumes(ParticleAnswer& answer, const ParticleSet& set, const ParticleRequest& request, int threads)
{
    answer.volume = request.volume.value_or(default_volume_model(set));
    answer.volumes = request.given_volumes.empty()
                         ? particle_volumes(set, answer.volume, threads)
                         : PerParticle::of(ParticleValues(request.given_volumes.begin(), request.given_volumes.end()));
    if (answer.volumes.size() != set.size())
        fail_input(fmt::format("volume: {} values for {} particles", answer.volumes.size(), set.size()));
    // Every pass over the particles on the request's threads, sums in fixed blocks (the same on any number).
    const auto& volumes = answer.volumes;
    if (const auto i = first_index_where(volumes.size(), threads,
                                         [&](std::size_t i) { return !std::isfinite(volumes[i]) || volumes[i] <= 0; }))
        fail_input(fmt::format("volume of particle {} is {}, expected a positive finite number", *i, volumes[*i]));
    const std::size_t measured = set.measured();
    const double total_volume = parallel_sum(measured, threads, [&](std::size_t i) { return volumes[i]; });
    answer.mean_volume = total_volume / static_cast<double>(measured);
    answer.spacing = set.spacing > 0 ? set.spacing : std::pow(answer.mean_volume, 1.0 / set.dimension);
    // The reference density: given, else the set's mean mass density, else 1 (m = rho0 V).
    answer.rho0 = request.rho0.value_or(1.0);
    if (!request.rho0 && !set.mass.empty())
        answer.rho0 = parallel_sum(measured, threads, [&](std::size_t i) { return set.mass[i]; }) / total_volume;
}

} // namespace

void finish_point(ParticlePoint& point, const Summary& h, double unit, double support, const ParticleSet& set,
                  double rho0)
{
    require_finite(point, set, rho0);
    point.eta = h.mean / unit;
    point.nh = neighbour_number(point.eta, support, set.dimension);
    point.h_min = h.min, point.h_max = h.max;
}

const Summary& ParticlePoint::statistic(const std::string& name) const
{
    for (const auto& [key, s] : statistics)
        if (key == name) return s;
    throw std::logic_error("no statistic " + name);
}

namespace {

// Every particle's h by `spec` and the measures at it. Where h comes from the SPH density with
// each particle's own h (and the measures' masses are the solve's), each particle is measured
// inside the solve from the neighbours it gathered: one search, not two (phase "h" then holds
// the sums too).
std::pair<PerParticle, ParticleMeasures> h_and_measures(const Kernel& kernel, const ParticleSet& set,
                                                        const SmoothingSpec& spec, const ParticleRequest& request,
                                                        ParticleAnswer& answer, int threads)
{
    PhaseTimes& phases = answer.phases;
    phases.restart();
    MeasureInputs inputs{{},
                         answer.volumes.view(),
                         set.mass,
                         answer.rho0,
                         answer.spacing,
                         request.depth,
                         answer.gravity,
                         request.threads,
                         request.vectors,
                         spec.pair};
    const bool same_masses = set.mass.empty() || !spec.by_number; // counted by number, the solve's masses are equal
    if (spec.rule == SmoothingRule::density && spec.pair == PairSmoothing::own && set.neighbours_only == 0 &&
        same_masses) {
        const auto t0 = std::chrono::steady_clock::now();
        const std::clock_t c0 = std::clock(); // the process's CPU time, every thread
        MeasureCollector collector(kernel, set, inputs, threads);
        PerParticle h = smoothing_lengths(set, kernel, spec, answer.mean_volume, threads, &collector);
        phases.lap("h");
        ParticleMeasures measures = collector.finish(); // its seconds: the solve's with the sums
        measures.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        measures.cpu_seconds = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
        return {std::move(h), std::move(measures)};
    }
    PerParticle h = smoothing_lengths(set, kernel, spec, answer.mean_volume, threads);
    phases.lap("h");
    inputs.h = h.view();
    ParticleMeasures measures = measure_particles(kernel, set, inputs);
    phases.merge(measures.phases);
    return {std::move(h), std::move(measures)};
}

} // namespace

ParticleAnswer analyse_particles(const Kernel& kernel, const ParticleSet& set, const ParticleRequest& request)
{
    kernel.require_dimension(set.dimension, set.name);
    ParticleAnswer answer;
    answer.particles = set.measured();
    PhaseTimes& phases = answer.phases;
    const int threads = worker_threads(request.threads);
    answer_volumes(answer, set, request, threads);
    phases.lap("volumes");
    answer.gravity = request.gravity ? request.gravity->normalized() : set.gravity;
    const std::size_t measured = set.measured();

    std::vector<SmoothingSpec> specs;
    if (const auto& s = request.sweep)
        for (int i = 0; i <= s->steps; ++i) specs.push_back({s->rule, s->from + (s->to - s->from) * i / s->steps, 0});
    else specs.push_back(request.smoothing);
    const int dim = set.dimension;
    const double R = kernel.support(), unit = std::pow(answer.mean_volume, 1.0 / dim);
    for (std::size_t p = 0; p < specs.size(); ++p) {
        auto [h, measures] = h_and_measures(kernel, set, specs[p], request, answer, threads);
        phases.restart();
        ParticlePoint point = summarise_point(measures, request.histogram_bins);
        // A particle that sees no other has no SPH sums to judge: h is too small for the set.
        if (point.statistics.back().second.min == 0) {
            const auto i = first_index_where(measures.size(), threads,
                                             [&](std::size_t i) { return measures.scalars[i].neighbours == 0; });
            fail_input(fmt::format("{}: {} has no neighbour inside its support (h = {:.6g}); expected a "
                                   "larger h or a denser set",
                                   set.name, set.particle(*i), h[*i]));
        }
        finish_point(point, statistics_detail::moments(measured, threads, [&](std::size_t i) { return h[i]; }), unit, R,
                     set, answer.rho0);
        answer.threads = measures.threads;
        phases.lap("statistics");
        if (specs.size() > 1)
            spdlog::debug("{}: {} of {} (h/l = {:.4g}, N_H = {:.4g})", set.name, p + 1, specs.size(), point.eta,
                          point.nh);
        answer.points.push_back(std::move(point));
        if (specs.size() == 1) answer.h = std::move(h), answer.measures = std::move(measures);
    }
    return answer;
}

} // namespace sphkern
