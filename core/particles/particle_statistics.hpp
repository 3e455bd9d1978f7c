// Statistics of a per-particle quantity over a set: mean, standard deviation, RMS, range and
// percentiles, and a histogram. Computed on several threads with the same bits on any number:
// moments per fixed block of particles, merged in block order; exact percentiles from integer
// counts and a selection.
#pragma once

#include "support/process/parallel_for.hpp"

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace sphkern {

struct Summary {
    double mean = 0, std = 0, rms = 0, min = 0, max = 0, p1 = 0, p50 = 0, p99 = 0;
};

namespace statistics_detail {

// The moments of one block: its mean and sum of squared deviations (two passes over a block
// that stays in cache), merged across blocks by Chan's formula.
struct Moments {
    double count = 0, mean = 0, m2 = 0, min = std::numeric_limits<double>::infinity(), max = -min;
};

// An unsigned key in the order of the doubles (-0 just below +0).
inline std::uint64_t order_key(double v)
{
    const auto bits = std::bit_cast<std::uint64_t>(v);
    return bits >> 63 ? ~bits : bits | (std::uint64_t{1} << 63);
}

// 65536 buckets of equal width in keys between the smallest value's key and the largest's: a
// histogram in value order, fine where the values crowd (a fixed slice of the key's top bits
// put a quarter of a set of magnitudes in one bucket, sorted out on one thread).
inline constexpr std::size_t buckets = std::size_t{1} << 16;
struct KeyBuckets {
    std::uint64_t lo = 0;
    int shift = 0;
    KeyBuckets(double min, double max);
    // Keys outside [min, max] (NaN) go to the last bucket.
    std::size_t of(std::uint64_t key) const { return std::min<std::uint64_t>((key - lo) >> shift, buckets - 1); }
};

// The percentiles from the threads' bucket counts (integers: the same whatever thread counted
// what) and a gather of the keys in the buckets of the ranks they need.
class Percentiles {
public:
    Percentiles(const std::vector<std::vector<std::uint32_t>>& counts, std::size_t n, const KeyBuckets& of, int threads);
    // The slot of a key's bucket among those to gather, -1 for none.
    int slot(std::uint64_t key) const { return slot_[of_.of(key)]; }
    std::size_t slots() const { return bucket_of_.size(); }
    // p1, p50, p99 from each thread's gathered keys per slot (any order within a slot).
    void finish(const std::vector<std::vector<std::vector<std::uint64_t>>>& parts, Summary& s) const;

private:
    std::size_t n_;
    KeyBuckets of_;
    int threads_;
    std::vector<std::uint64_t> first_; // first rank of each bucket
    std::vector<std::int8_t> slot_;
    std::vector<std::size_t> bucket_of_, ranks_;
};

Summary merge_moments(const std::vector<Moments>& blocks);

// The moments of value(i) over [0, n), block by block.
template <class Value>
Summary moments(std::size_t n, int threads, const Value& value)
{
    std::vector<Moments> blocks((n + particle_block_size - 1) / particle_block_size);
    ParallelFor pass;
    pass.run_blocks(n, particle_block_size, threads, [&](std::size_t b, std::size_t begin, std::size_t end) {
        Moments& m = blocks[b];
        double sum = 0;
        for (std::size_t i = begin; i < end; ++i) {
            const double v = value(i);
            sum += v, m.min = std::min(m.min, v), m.max = std::max(m.max, v);
        }
        m.count = static_cast<double>(end - begin), m.mean = sum / m.count;
        for (std::size_t i = begin; i < end; ++i) m.m2 += (value(i) - m.mean) * (value(i) - m.mean);
    });
    return merge_moments(blocks);
}

} // namespace statistics_detail

// Mean, std, RMS and range only (no percentiles) of `values`, the same on any thread count.
inline Summary summarise_moments(std::span<const double> values, int threads = 1)
{
    return statistics_detail::moments(values.size(), threads, [&](std::size_t i) { return values[i]; });
}

// The summary of value(i) over i in [0, n) (n > 0) on `threads` threads: std is the population
// standard deviation; percentiles interpolate linearly between order statistics (numpy's
// default), which are exact. The same bits on any number of threads. value(i) is called four
// times per item (two passes over each block, a count and a gather), so it may compute the value.
template <class Value>
Summary summarise_values(std::size_t n, int threads, const Value& value)
{
    using namespace statistics_detail;
    Summary s = moments(n, threads, value);
    const KeyBuckets of(s.min, s.max);
    // A thread counts into its own buckets (allocated and first touched by it): one thread per 65536 values at most.
    const int workers = std::clamp<int>(threads, 1, static_cast<int>(n / buckets + 1));
    std::vector<std::vector<std::uint32_t>> counts(static_cast<std::size_t>(workers));
    ParallelFor counting;
    counting.run(n, workers, [&](int t, std::size_t begin, std::size_t end) {
        auto& c = counts[static_cast<std::size_t>(t)];
        c.assign(buckets, 0);
        for (std::size_t i = begin; i < end; ++i) ++c[of.of(order_key(value(i)))];
    });
    const Percentiles percentiles(counts, n, of, workers);
    std::vector<std::vector<std::vector<std::uint64_t>>> parts(static_cast<std::size_t>(workers));
    ParallelFor gathering;
    gathering.run(n, workers, [&](int t, std::size_t begin, std::size_t end) {
        auto& part = parts[static_cast<std::size_t>(t)];
        part.resize(percentiles.slots());
        for (std::size_t i = begin; i < end; ++i) {
            const std::uint64_t key = order_key(value(i));
            if (const int k = percentiles.slot(key); k >= 0) part[static_cast<std::size_t>(k)].push_back(key);
        }
    });
    percentiles.finish(parts, s);
    return s;
}

inline Summary summarise(std::span<const double> values, int threads = 1)
{
    return summarise_values(values.size(), threads, [&](std::size_t i) { return values[i]; });
}

struct Histogram {
    double lo = 0, hi = 0;
    std::vector<std::size_t> counts; // equal bins over [lo, hi], the last one closed
};
Histogram histogram(std::span<const double> values, std::size_t bins, int threads = 1);

} // namespace sphkern
