#include "relax/glass_quality.hpp"

#include "particles/engine/neighbour_gather.hpp"
#include "particles/engine/pair_pass.hpp"
#include "support/error.hpp"
#include "support/process/parallel_for.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sphkern {

namespace {

// Calls visit(thread, i, neighbours within `reach`) for every particle, in parallel.
template <class Visit>
void visit_neighbours(const ParticleSet& set, double reach, int threads, int thread_slots, const Visit& visit)
{
    if (!set.box) fail_input(fmt::format("{}: g(r) and nearest neighbours need a periodic box", set.name));
    const NeighbourGrid grid(set, reach, threads);
    pair_pass(
        grid, set.name, {{nullptr, reach}, nullptr, nullptr, true, ""}, std::min(threads, thread_slots),
        [&](int thread, std::size_t p, Neighbours& nb) {
            fill_distances(nb);
            visit(thread, grid.source(p), nb);
        },
        [](int) {});
}

int thread_count(int threads) { return std::clamp(threads, 1, 64); }

// The share of nearest-neighbour distances (in units of l) below 0.5.
double paired_share(const std::vector<double>& nearest)
{
    return static_cast<double>(std::count_if(nearest.begin(), nearest.end(), [](double r) { return r < 0.5; })) /
           static_cast<double>(nearest.size());
}

} // namespace

std::vector<double> nearest_distances(const ParticleSet& set, int threads)
{
    const double l = mean_spacing(set);
    // Every particle has a neighbour within 2 l except in sets far from uniform; those few are searched farther.
    std::vector<double> nearest(set.size(), INFINITY);
    for (double reach = 2 * l;; reach *= 2) {
        const bool last = 2 * reach * 2 > set.box->smallest_width(set.dimension);
        const double used = last ? set.box->smallest_width(set.dimension) / 2 * (1 - 1e-9) : reach;
        visit_neighbours(set, used, thread_count(threads), 64, [&](int, std::size_t i, const Neighbours& nb) {
            for (std::size_t j = 0; j < nb.count; ++j) nearest[i] = std::min(nearest[i], nb.r[j]);
        });
        const bool done = std::none_of(nearest.begin(), nearest.end(), [](double r) { return std::isinf(r); });
        if (done || last) break;
    }
    if (std::any_of(nearest.begin(), nearest.end(), [](double r) { return std::isinf(r); }))
        fail_input(fmt::format("{}: a particle has no neighbour within half the box", set.name));
    return nearest;
}

double paired_fraction(const ParticleSet& set, int threads)
{
    std::vector<double> nearest = nearest_distances(set, threads);
    const double l = mean_spacing(set);
    for (double& r : nearest) r /= l;
    return paired_share(nearest);
}

void check_rdf_settings(double r_max, std::size_t bins, const ValueSource& r_max_source, const ValueSource& bins_source)
{
    check_range(static_cast<double>(bins), 1, 100000, bins_source);
    if (!(r_max > 0.5) || !std::isfinite(r_max))
        throw Error(r_max_source.code,
                    r_max_source.about(r_max) + ": expected a finite number above 0.5 (mean spacings)");
}

GlassQuality glass_quality(const ParticleSet& set, double r_max, std::size_t bins, int threads)
{
    if (!set.box) fail_input(fmt::format("{}: g(r) and nearest neighbours need a periodic box", set.name));
    check_rdf_settings(r_max, bins, ValueSource::argument("g(r) range"), ValueSource::argument("g(r) bins"));
    const double l = mean_spacing(set), width = set.box->smallest_width(set.dimension);
    r_max = std::min(r_max, width / 2 / l * (1 - 1e-9));
    if (!(r_max > 0.5))
        fail_input(fmt::format("{}: the box is {:.3g} mean spacings wide; g(r) needs at least 1", set.name, width / l));
    const int t = thread_count(threads);
    std::vector<std::vector<double>> counts(static_cast<std::size_t>(t), std::vector<double>(bins, 0.0));
    const double width_bin = r_max / static_cast<double>(bins);
    visit_neighbours(set, r_max * l, t, t, [&](int thread, std::size_t, const Neighbours& nb) {
        auto& c = counts[static_cast<std::size_t>(thread)];
        for (std::size_t j = 0; j < nb.count; ++j) {
            const auto b = static_cast<std::size_t>(nb.r[j] / l / width_bin);
            if (b < bins) c[b] += 1;
        }
    });
    GlassQuality q;
    q.rdf.bin_width = width_bin;
    const double n = static_cast<double>(set.size());
    for (std::size_t b = 0; b < bins; ++b) {
        double total = 0;
        for (const auto& c : counts) total += c[b]; // whole numbers: the sum is exact in any order
        const double lo = static_cast<double>(b) * width_bin, hi = lo + width_bin;
        // Over the count of an ideal gas of the other n - 1 particles in the shell (volumes in l^D).
        const double shell = set.dimension == 3 ? 4.0 / 3.0 * std::numbers::pi * (hi * hi * hi - lo * lo * lo)
                                                : std::numbers::pi * (hi * hi - lo * lo);
        const double g = total / ((n - 1) * shell);
        q.rdf.r.push_back((lo + hi) / 2);
        q.rdf.g.push_back(g);
        if (g > q.rdf.peak) q.rdf.peak = g, q.rdf.peak_r = (lo + hi) / 2;
    }
    std::vector<double> nearest = nearest_distances(set, threads);
    for (double& r : nearest) r /= l;
    q.paired = paired_share(nearest);
    q.nearest_histogram = histogram(nearest, 30);
    q.nearest = summarise(std::move(nearest));
    return q;
}

} // namespace sphkern
