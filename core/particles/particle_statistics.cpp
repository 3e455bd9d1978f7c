#include "particles/particle_statistics.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace sphkern {

namespace statistics_detail {

KeyBuckets::KeyBuckets(double min, double max) : lo(order_key(min))
{
    const std::uint64_t span = order_key(max) - lo;
    shift = std::max(0, static_cast<int>(std::bit_width(span)) - 16);
}

namespace {

double from_key(std::uint64_t key) { return std::bit_cast<double>(key >> 63 ? key & ~(std::uint64_t{1} << 63) : ~key); }

constexpr double percentile_p[] = {0.01, 0.5, 0.99};

// The key of rank `rank` among `keys` (in any order), whose offsets from `base` are alike
// above bit `shift` (one bucket): radix steps of 16 bits of the offsets narrow them to one
// value or a few thousand keys, then a selection. Linear in the keys, however they crowd (a
// bucket of integers holds a whole value's particles).
std::uint64_t select_key(std::vector<std::uint64_t> keys, std::size_t rank, std::uint64_t base, int shift)
{
    constexpr std::size_t few = 4096;
    while (keys.size() > few && shift > 0) {
        shift = std::max(0, shift - 16);
        auto digit_of = [&](std::uint64_t k) { return ((k - base) >> shift) & 0xFFFF; };
        std::vector<std::uint32_t> count(std::size_t{1} << 16, 0);
        std::uint64_t lo = keys.front(), hi = lo;
        for (std::uint64_t k : keys) ++count[digit_of(k)], lo = std::min(lo, k), hi = std::max(hi, k);
        if (lo == hi) return lo; // one value
        std::uint64_t digit = 0;
        while (rank >= count[digit]) rank -= count[digit++];
        std::erase_if(keys, [&](std::uint64_t k) { return digit_of(k) != digit; });
    }
    std::nth_element(keys.begin(), keys.begin() + static_cast<std::ptrdiff_t>(rank), keys.end());
    return keys[rank];
}

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

// Ranks floor(p (n - 1)) and the one above for each percentile, and the bucket of each rank.
Percentiles::Percentiles(const std::vector<std::vector<std::uint32_t>>& counts, std::size_t n, const KeyBuckets& of,
                         int threads)
    : n_(n), of_(of), threads_(threads), first_(buckets + 1, 0), slot_(buckets, -1)
{
    // The threads' counts added bucket by bucket in parallel, then the running sum.
    ParallelFor adding;
    adding.run(buckets, threads, [&](int, std::size_t begin, std::size_t end) {
        for (std::size_t b = begin; b < end; ++b)
            for (const auto& c : counts) first_[b + 1] += c[b];
    });
    for (std::size_t b = 0; b < buckets; ++b) first_[b + 1] += first_[b];
    for (double p : percentile_p) {
        const auto lo = static_cast<std::size_t>(std::floor(p * static_cast<double>(n - 1)));
        ranks_.push_back(lo), ranks_.push_back(std::min(lo + 1, n - 1));
    }
    for (std::size_t rank : ranks_) {
        const auto b =
            static_cast<std::size_t>(std::upper_bound(first_.begin(), first_.end(), rank) - first_.begin() - 1);
        if (slot_[b] < 0) slot_[b] = static_cast<std::int8_t>(bucket_of_.size()), bucket_of_.push_back(b);
    }
}

void Percentiles::finish(const std::vector<std::vector<std::vector<std::uint64_t>>>& parts, Summary& s) const
{
    // Each rank on a thread of its own, with its bucket's keys from every thread: the k-th key
    // is one value, in any order of gathering.
    std::vector<double> at(ranks_.size());
    ParallelFor select;
    select.run(ranks_.size(), std::min(threads_, static_cast<int>(ranks_.size())),
               [&](int, std::size_t begin, std::size_t end) {
                   for (std::size_t r = begin; r < end; ++r) {
                       const auto b = static_cast<std::size_t>(
                           std::upper_bound(first_.begin(), first_.end(), ranks_[r]) - first_.begin() - 1);
                       const auto slot = static_cast<std::size_t>(slot_[b]);
                       std::vector<std::uint64_t> keys;
                       keys.reserve(first_[b + 1] - first_[b]);
                       for (const auto& part : parts)
                           if (slot < part.size()) keys.insert(keys.end(), part[slot].begin(), part[slot].end());
                       at[r] = from_key(select_key(std::move(keys), ranks_[r] - first_[b], of_.lo, of_.shift));
                   }
               });
    // numpy's linear interpolation between the order statistics at floor(rank) and the one above.
    double* out[] = {&s.p1, &s.p50, &s.p99};
    for (std::size_t k = 0; k < 3; ++k) {
        const double rank = percentile_p[k] * static_cast<double>(n_ - 1);
        *out[k] = at[2 * k] + (rank - std::floor(rank)) * (at[2 * k + 1] - at[2 * k]);
    }
}

} // namespace statistics_detail

void ExactSummary::fold_counts()
{
    auto& total = counts_.front();
    for (std::size_t t = 1; t < counts_.size(); ++t)
        for (std::size_t b = 0; b < statistics_detail::buckets; ++b) total[b] += counts_[t][b];
    counts_.resize(1);
}

Histogram histogram(std::span<const double> values, std::size_t bins, int threads)
{
    const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
    Histogram h(*lo, *hi, bins);
    h.add(values, threads);
    return h;
}

} // namespace sphkern
