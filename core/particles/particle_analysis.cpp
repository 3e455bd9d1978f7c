#include "particles/particle_analysis.hpp"

#include "support/error.hpp"
#include "support/process/parallel_for.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace sphkern {

namespace {

ParticlePoint summarise_point(const ParticleMeasures& m, std::size_t bins)
{
    ParticlePoint point;
    const int threads = m.threads;
    const std::span<const double> fields[] = {m.e0, m.eps_rho_values(), m.eps_gradp, m.eps_gradp_sum, m.e1_norm, m.m1_norm, m.E_norm};
    for (std::size_t f = 0; f < std::size(fields); ++f) {
        // Without masses eps_rho is e0: its summary is e0's.
        const bool same = f > 0 && fields[f].data() == m.e0.data();
        point.statistics.emplace_back(measure_names[f], same ? point.statistics.front().second : summarise(fields[f], threads));
    }
    point.statistics.emplace_back(
        measure_names[7], summarise_values(m.size(), threads, [&](std::size_t i) { return static_cast<double>(m.neighbours[i]); }));
    if (bins)
        for (std::size_t f = 0; f < measures_with_histograms; ++f)
            point.histograms.emplace_back(measure_names[f], histogram(fields[f], bins, threads));
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
    if (const auto i = first_index_where(volumes.size(), threads, [&](std::size_t i) { return !std::isfinite(volumes[i]) || volumes[i] <= 0; }))
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

void finish_point(ParticlePoint& point, const Summary& h, double unit, double support, const ParticleSet& set, double rho0)
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
        for (int i = 0; i <= s->steps; ++i)
            specs.push_back({s->rule, s->from + (s->to - s->from) * i / s->steps, 0});
    else specs.push_back(request.smoothing);
    const int dim = set.dimension;
    const double R = kernel.support(), unit = std::pow(answer.mean_volume, 1.0 / dim);
    for (std::size_t p = 0; p < specs.size(); ++p) {
        phases.restart();
        auto h = smoothing_lengths(set, kernel, specs[p], answer.mean_volume, threads);
        phases.lap("h");
        MeasureInputs inputs{h.view(), answer.volumes.view(), set.mass, answer.rho0, answer.spacing, request.depth, answer.gravity,
                             request.threads, request.vectors, specs[p].pair};
        auto measures = measure_particles(kernel, set, inputs);
        phases.merge(measures.phases);
        phases.restart();
        // A particle that sees no other has no SPH sums to judge: h is too small for the set.
        if (const auto i = first_index_where(measures.size(), threads, [&](std::size_t i) { return measures.neighbours[i] == 0; }))
            fail_input(fmt::format("{}: particle {} has no neighbour inside its support (h = {:.6g}); expected a "
                                   "larger h or a denser set",
                                   set.name, *i, h[*i]));
        ParticlePoint point = summarise_point(measures, request.histogram_bins);
        finish_point(point, statistics_detail::moments(measured, threads, [&](std::size_t i) { return h[i]; }), unit, R, set, answer.rho0);
        answer.threads = measures.threads;
        phases.lap("statistics");
        if (specs.size() > 1) spdlog::debug("{}: {} of {} (h/l = {:.4g}, N_H = {:.4g})", set.name, p + 1, specs.size(), point.eta, point.nh);
        answer.points.push_back(std::move(point));
        if (specs.size() == 1) answer.h = std::move(h), answer.measures = std::move(measures);
    }
    return answer;
}

} // namespace sphkern
