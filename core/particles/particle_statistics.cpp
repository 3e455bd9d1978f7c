#include "particles/particle_statistics.hpp"

#include "support/process/parallel_for.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace sphkern {

namespace {

// An unsigned key in the order of the doubles (-0 just below +0): selecting by key is
// selecting by value, and a key's top bits are a bucket of a histogram in that order.
std::uint64_t order_key(double v)
{
    const auto bits = std::bit_cast<std::uint64_t>(v);
    return bits >> 63 ? ~bits : bits | (std::uint64_t{1} << 63);
}

double from_key(std::uint64_t key)
{
    return std::bit_cast<double>(key >> 63 ? key & ~(std::uint64_t{1} << 63) : ~key);
}

// The values at the given ranks (0-based, ascending order), exactly: one parallel histogram of
// the keys' top 16 bits finds each rank's bucket, and a selection among that bucket's values
// (a small share of them unless the values crowd into one bucket) finds the rank within it.
std::vector<double> order_statistics(std::span<const double> values, const std::vector<std::size_t>& ranks,
                                     int threads)
{
    constexpr int shift = 48;
    constexpr std::size_t buckets = std::size_t{1} << 16;
    threads = std::clamp<int>(threads, 1, static_cast<int>(values.size() / particle_block_size + 1));
    std::vector<std::vector<std::uint32_t>> counts(static_cast<std::size_t>(threads));
    ParallelFor counting;
    counting.run(values.size(), threads, [&](int t, std::size_t begin, std::size_t end) {
        auto& c = counts[static_cast<std::size_t>(t)];
        c.assign(buckets, 0);
        for (std::size_t i = begin; i < end; ++i) ++c[order_key(values[i]) >> shift];
    });
    // The first rank of every bucket: integer counts, the same on any thread count.
    std::vector<std::uint64_t> first(buckets + 1, 0);
    for (std::size_t b = 0; b < buckets; ++b) {
        first[b + 1] = first[b];
        for (const auto& c : counts) first[b + 1] += c[b];
    }
    // The keys of the buckets that hold a rank, gathered in one pass (slot -1: no rank in the bucket).
    std::vector<std::size_t> bucket_of;
    std::vector<std::int8_t> slot(buckets, -1);
    for (std::size_t rank : ranks) {
        const auto b = static_cast<std::size_t>(std::upper_bound(first.begin(), first.end(), rank) - first.begin() - 1);
        if (slot[b] < 0) slot[b] = static_cast<std::int8_t>(bucket_of.size()), bucket_of.push_back(b);
    }
    std::vector<std::vector<std::vector<std::uint64_t>>> parts(static_cast<std::size_t>(threads),
                                                               std::vector<std::vector<std::uint64_t>>(bucket_of.size()));
    ParallelFor gathering;
    gathering.run(values.size(), threads, [&](int t, std::size_t begin, std::size_t end) {
        auto& part = parts[static_cast<std::size_t>(t)];
        for (std::size_t i = begin; i < end; ++i) {
            const std::uint64_t key = order_key(values[i]);
            if (const int k = slot[key >> shift]; k >= 0) part[static_cast<std::size_t>(k)].push_back(key);
        }
    });
    std::vector<std::vector<std::uint64_t>> keys(bucket_of.size());
    for (std::size_t k = 0; k < keys.size(); ++k)
        for (const auto& part : parts) keys[k].insert(keys[k].end(), part[k].begin(), part[k].end());
    std::vector<double> out;
    for (std::size_t rank : ranks) {
        const auto b = static_cast<std::size_t>(std::upper_bound(first.begin(), first.end(), rank) - first.begin() - 1);
        auto& bucket = keys[static_cast<std::size_t>(slot[b])];
        const auto at = bucket.begin() + static_cast<std::ptrdiff_t>(rank - first[b]);
        std::nth_element(bucket.begin(), at, bucket.end()); // the k-th key is one value, in any order of gathering
        out.push_back(from_key(*at));
    }
    return out;
}

// The p-quantile from the order statistics at floor(rank) and the one above it (numpy's linear).
double interpolate(double p, std::size_t n, double below, double above)
{
    const double rank = p * static_cast<double>(n - 1);
    return below + (rank - std::floor(rank)) * (above - below);
}

struct Sums {
    double sum = 0, squares = 0, min = std::numeric_limits<double>::infinity(), max = -min;
};

} // namespace

// Sums are taken over fixed blocks and the blocks' sums added in block order (parallel_reduce),
// so that they do not depend on the thread count.
Summary summarise(std::span<const double> values, int threads)
{
    Summary s;
    const std::size_t count = values.size();
    const double n = static_cast<double>(count);
    const Sums total = parallel_reduce(
        count, threads, Sums{},
        [&](std::size_t i, Sums& a) {
            const double v = values[i];
            a.sum += v, a.squares += v * v, a.min = std::min(a.min, v), a.max = std::max(a.max, v);
        },
        [](Sums& a, const Sums& b) { a.sum += b.sum, a.squares += b.squares, a.min = std::min(a.min, b.min), a.max = std::max(a.max, b.max); });
    s.mean = total.sum / n;
    s.rms = std::sqrt(total.squares / n);
    s.min = total.min, s.max = total.max;
    const double deviation = parallel_sum(count, threads, [&](std::size_t i) { return (values[i] - s.mean) * (values[i] - s.mean); });
    s.std = std::sqrt(deviation / n);
    // Ranks floor(p (n - 1)) and the one above, for p = 0.01, 0.5 and 0.99.
    const double ps[] = {0.01, 0.5, 0.99};
    std::vector<std::size_t> ranks;
    for (double p : ps) {
        const auto lo = static_cast<std::size_t>(std::floor(p * (n - 1)));
        ranks.push_back(lo), ranks.push_back(std::min(lo + 1, count - 1));
    }
    const auto at = order_statistics(values, ranks, threads);
    s.p1 = interpolate(ps[0], count, at[0], at[1]);
    s.p50 = interpolate(ps[1], count, at[2], at[3]);
    s.p99 = interpolate(ps[2], count, at[4], at[5]);
    return s;
}

Histogram histogram(std::span<const double> values, std::size_t bins, int threads)
{
    Histogram h;
    const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
    h.lo = *lo, h.hi = *hi;
    const double width = (h.hi - h.lo) / static_cast<double>(bins);
    threads = std::clamp<int>(threads, 1, static_cast<int>(values.size() / particle_block_size + 1));
    std::vector<std::vector<std::size_t>> counts(static_cast<std::size_t>(threads));
    ParallelFor pass;
    pass.run(values.size(), threads, [&](int t, std::size_t begin, std::size_t end) {
        auto& c = counts[static_cast<std::size_t>(t)];
        c.assign(bins, 0);
        for (std::size_t i = begin; i < end; ++i) {
            const std::size_t b = width > 0 ? static_cast<std::size_t>((values[i] - h.lo) / width) : 0;
            c[std::min(b, bins - 1)] += 1;
        }
    });
    h.counts.assign(bins, 0);
    for (const auto& c : counts)
        for (std::size_t b = 0; b < bins; ++b) h.counts[b] += c[b];
    return h;
}

} // namespace sphkern
