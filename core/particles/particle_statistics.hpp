// Statistics of a per-particle quantity over a set: mean, standard deviation, RMS, range and
// percentiles, and a histogram.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace sphkern {

struct Summary {
    double mean = 0, std = 0, rms = 0, min = 0, max = 0, p1 = 0, p50 = 0, p99 = 0;
};

// std is the population standard deviation; percentiles interpolate linearly between
// order statistics (numpy's default), which are exact. The same on any number of threads.
// `values` must not be empty.
Summary summarise(std::span<const double> values, int threads = 1);

struct Histogram {
    double lo = 0, hi = 0;
    std::vector<std::size_t> counts; // equal bins over [lo, hi], the last one closed
};
Histogram histogram(std::span<const double> values, std::size_t bins, int threads = 1);

} // namespace sphkern
