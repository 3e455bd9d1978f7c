#include "particles/particle_statistics.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace sphkern {

namespace statistics_detail {

std::uint64_t order_key(double v)
{
    const auto bits = std::bit_cast<std::uint64_t>(v);
    return bits >> 63 ? ~bits : bits | (std::uint64_t{1} << 63);
}

namespace {

double from_key(std::uint64_t key) { return std::bit_cast<double>(key >> 63 ? key & ~(std::uint64_t{1} << 63) : ~key); }

constexpr double percentile_p[] = {0.01, 0.5, 0.99};

} // namespace

Summary merge_moments(const std::vector<Moments>& blocks)
{
    Moments total;
    for (const Moments& b : blocks) {
        const double count = total.count + b.count, delta = b.mean - total.mean;
        total.mean += delta * b.count / count;
        total.m2 += b.m2 + delta * delta * total.count * b.count / count;
        total.count = count, total.min = std::min(total.min, b.min), total.max = std::max(total.max, b.max);
    }
    Summary s;
    s.mean = total.mean, s.min = total.min, s.max = total.max;
    s.std = std::sqrt(total.m2 / total.count);
    s.rms = std::sqrt(total.m2 / total.count + total.mean * total.mean);
    return s;
}

// Ranks floor(p (n - 1)) and the one above for each percentile; the bucket of each rank from
// the counts (integers: the same whatever thread counted what).
Percentiles::Percentiles(const std::vector<std::vector<std::uint32_t>>& counts, std::size_t n)
    : n_(n), first_(buckets + 1, 0), slot_(buckets, -1)
{
    for (std::size_t b = 0; b < buckets; ++b) {
        first_[b + 1] = first_[b];
        for (const auto& c : counts)
            if (!c.empty()) first_[b + 1] += c[b];
    }
    for (double p : percentile_p) {
        const auto lo = static_cast<std::size_t>(std::floor(p * static_cast<double>(n - 1)));
        ranks_.push_back(lo), ranks_.push_back(std::min(lo + 1, n - 1));
    }
    for (std::size_t rank : ranks_) {
        const auto b = static_cast<std::size_t>(std::upper_bound(first_.begin(), first_.end(), rank) - first_.begin() - 1);
        if (slot_[b] < 0) slot_[b] = static_cast<std::int8_t>(bucket_of_.size()), bucket_of_.push_back(b);
    }
}

void Percentiles::finish(std::vector<std::vector<std::uint64_t>>& keys, Summary& s) const
{
    std::vector<double> at;
    for (std::size_t rank : ranks_) {
        const auto b = static_cast<std::size_t>(std::upper_bound(first_.begin(), first_.end(), rank) - first_.begin() - 1);
        auto& bucket = keys[static_cast<std::size_t>(slot_[b])];
        const auto it = bucket.begin() + static_cast<std::ptrdiff_t>(rank - first_[b]);
        std::nth_element(bucket.begin(), it, bucket.end()); // the k-th key is one value, in any order of gathering
        at.push_back(from_key(*it));
    }
    // numpy's linear interpolation between the order statistics at floor(rank) and the one above.
    double* out[] = {&s.p1, &s.p50, &s.p99};
    for (std::size_t k = 0; k < 3; ++k) {
        const double rank = percentile_p[k] * static_cast<double>(n_ - 1);
        *out[k] = at[2 * k] + (rank - std::floor(rank)) * (at[2 * k + 1] - at[2 * k]);
    }
}

} // namespace statistics_detail

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
