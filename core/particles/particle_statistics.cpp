#include "particles/particle_statistics.hpp"

#include <algorithm>
#include <cmath>

namespace sphkern {

namespace {

// The p-quantile, interpolated between neighbouring ranks: two selections instead of a sort.
double quantile(std::vector<double>& values, double p)
{
    const double rank = p * static_cast<double>(values.size() - 1);
    const std::size_t lo = static_cast<std::size_t>(std::floor(rank));
    const auto at = [&](std::size_t r) {
        std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(r), values.end());
        return values[r];
    };
    const double below = at(lo);
    if (lo + 1 >= values.size() || rank == static_cast<double>(lo)) return below;
    // The next order statistic is the smallest value above rank lo.
    const double above = *std::min_element(values.begin() + static_cast<std::ptrdiff_t>(lo) + 1, values.end());
    return below + (rank - static_cast<double>(lo)) * (above - below);
}

} // namespace

Summary summarise(std::vector<double> values)
{
    Summary s;
    const double n = static_cast<double>(values.size());
    double sum = 0, squares = 0;
    for (double v : values) sum += v, squares += v * v;
    s.mean = sum / n;
    s.rms = std::sqrt(squares / n);
    double deviation = 0;
    for (double v : values) deviation += (v - s.mean) * (v - s.mean);
    s.std = std::sqrt(deviation / n);
    const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
    s.min = *lo, s.max = *hi;
    s.p1 = quantile(values, 0.01), s.p50 = quantile(values, 0.5), s.p99 = quantile(values, 0.99);
    return s;
}

Histogram histogram(const std::vector<double>& values, std::size_t bins)
{
    Histogram h;
    const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
    h.lo = *lo, h.hi = *hi;
    h.counts.assign(bins, 0);
    const double width = (h.hi - h.lo) / static_cast<double>(bins);
    for (double v : values) {
        std::size_t b = width > 0 ? static_cast<std::size_t>((v - h.lo) / width) : 0;
        h.counts[std::min(b, bins - 1)] += 1;
    }
    return h;
}

} // namespace sphkern
