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
#include <optional>
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
    Percentiles(const std::vector<std::vector<std::uint32_t>>& counts, std::size_t n, const KeyBuckets& of,
                int threads);
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

// The threads that count `count` values, each into buckets of its own (first touched by it):
// one per 65536 values at most, as more would spend longer on their buckets than on the values.
inline int counting_threads(std::size_t count, int threads)
{
    return std::clamp<int>(threads, 1, static_cast<int>(count / buckets + 1));
}

} // namespace statistics_detail

// The exact summary of n values that arrive in index order, in runs [begin, begin + count)
// whose begin is a multiple of particle_block_size (the whole range at once, or a file read
// chunk by chunk): three passes over the values, each taking every run in order. The moments
// are per fixed block of particle_block_size, merged in block order, and the percentiles come
// from integer counts and a selection of the keys in the ranks' buckets, so the bits depend
// neither on the thread count nor on how the values were cut into runs.
class ExactSummary {
public:
    explicit ExactSummary(std::size_t n) : n_(n), blocks_((n + particle_block_size - 1) / particle_block_size) {}

    // Pass 1: the moments of each block of the run (two passes over a block in cache).
    template <class Value>
    void add_moments(std::size_t begin, std::size_t count, int threads, const Value& value)
    {
        using namespace statistics_detail;
        ParallelFor pass;
        pass.run_blocks(count, particle_block_size, threads, [&](std::size_t b, std::size_t from, std::size_t to) {
            Moments& m = blocks_[begin / particle_block_size + b];
            double sum = 0;
            for (std::size_t i = from; i < to; ++i) {
                const double v = value(i);
                sum += v, m.min = std::min(m.min, v), m.max = std::max(m.max, v);
            }
            m.count = static_cast<double>(to - from), m.mean = sum / m.count;
            for (std::size_t i = from; i < to; ++i) m.m2 += (value(i) - m.mean) * (value(i) - m.mean);
        });
    }
    // Mean, std, RMS and range: the moments alone.
    Summary moments() const { return statistics_detail::merge_moments(blocks_); }

    // Pass 2: each value's bucket counted (on counting_threads).
    template <class Value>
    void count(std::size_t count, int threads, const Value& value)
    {
        using namespace statistics_detail;
        if (!buckets_) summary_ = moments(), buckets_.emplace(summary_.min, summary_.max);
        const int workers = counting_threads(count, threads);
        const std::size_t first = counts_.size();
        counts_.resize(first + static_cast<std::size_t>(workers));
        ParallelFor counting;
        counting.run(count, workers, [&](int t, std::size_t from, std::size_t to) {
            auto& c = counts_[first + static_cast<std::size_t>(t)];
            c.assign(buckets, 0);
            for (std::size_t i = from; i < to; ++i) ++c[buckets_->of(order_key(value(i)))];
        });
        // The counts so far in one: memory stays one set of buckets per thread, however many runs.
        if (counts_.size() > static_cast<std::size_t>(workers)) fold_counts();
    }

    // Pass 3: the keys in the buckets of the percentiles' ranks gathered.
    template <class Value>
    void gather(std::size_t count, int threads, const Value& value)
    {
        using namespace statistics_detail;
        if (!percentiles_) percentiles_.emplace(counts_, n_, *buckets_, std::max(1, threads)), counts_.clear();
        const int workers = counting_threads(count, threads);
        const std::size_t first = parts_.size();
        parts_.resize(first + static_cast<std::size_t>(workers));
        ParallelFor gathering;
        gathering.run(count, workers, [&](int t, std::size_t from, std::size_t to) {
            auto& part = parts_[first + static_cast<std::size_t>(t)];
            part.resize(percentiles_->slots());
            for (std::size_t i = from; i < to; ++i) {
                const std::uint64_t key = order_key(value(i));
                if (const int k = percentiles_->slot(key); k >= 0) part[static_cast<std::size_t>(k)].push_back(key);
            }
        });
    }

    // After the three passes: the whole summary.
    Summary finish() const
    {
        Summary s = summary_;
        percentiles_->finish(parts_, s);
        return s;
    }

private:
    void fold_counts();
    std::size_t n_;
    std::vector<statistics_detail::Moments> blocks_;
    Summary summary_;
    std::optional<statistics_detail::KeyBuckets> buckets_;
    std::vector<std::vector<std::uint32_t>> counts_;
    std::optional<statistics_detail::Percentiles> percentiles_;
    std::vector<std::vector<std::vector<std::uint64_t>>> parts_;
};

namespace statistics_detail {

// The moments of value(i) over [0, n), block by block.
template <class Value>
Summary moments(std::size_t n, int threads, const Value& value)
{
    ExactSummary summary(n);
    summary.add_moments(0, n, threads, value);
    return summary.moments();
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
    ExactSummary summary(n);
    summary.add_moments(0, n, threads, value);
    summary.count(n, threads, value);
    summary.gather(n, threads, value);
    return summary.finish();
}

inline Summary summarise(std::span<const double> values, int threads = 1)
{
    return summarise_values(values.size(), threads, [&](std::size_t i) { return values[i]; });
}

struct Histogram {
    double lo = 0, hi = 0;
    std::vector<std::size_t> counts; // equal bins over [lo, hi], the last one closed

    Histogram(double lo, double hi, std::size_t bins) : lo(lo), hi(hi), counts(bins, 0) {}
    Histogram() = default;
    // Counts `values` into the bins (integers: in any order, in any runs).
    void add(std::span<const double> values, int threads = 1)
    {
        add_values(values.size(), threads, [&](std::size_t i) { return values[i]; });
    }
    // Counts value(i) for i in [0, n).
    template <class Value>
    void add_values(std::size_t n, int threads, const Value& value);
};
Histogram histogram(std::span<const double> values, std::size_t bins, int threads = 1);

template <class Value>
void Histogram::add_values(std::size_t n, int threads, const Value& value)
{
    const std::size_t bins = counts.size();
    const double width = (hi - lo) / static_cast<double>(bins);
    threads = statistics_detail::counting_threads(n, threads);
    std::vector<std::vector<std::size_t>> parts(static_cast<std::size_t>(threads));
    ParallelFor pass;
    pass.run(n, threads, [&](int t, std::size_t begin, std::size_t end) {
        auto& c = parts[static_cast<std::size_t>(t)];
        c.assign(bins, 0);
        for (std::size_t i = begin; i < end; ++i) {
            const std::size_t b = width > 0 ? static_cast<std::size_t>((value(i) - lo) / width) : 0;
            c[std::min(b, bins - 1)] += 1;
        }
    });
    for (const auto& c : parts)
        for (std::size_t b = 0; b < bins; ++b) counts[b] += c[b];
}

} // namespace sphkern
