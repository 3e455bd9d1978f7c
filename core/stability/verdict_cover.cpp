#include "stability/verdict_cover.hpp"

#include "stability/brillouin_zone.hpp"
#include "stability/dispersion_jumps.hpp"
#include "stability/verdict_span.hpp"
#include "support/error.hpp"

#include "support/process/parallel_for.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <optional>
#include <utility>

namespace sphkern {

namespace {

constexpr StabilityRule rules[] = {StabilityRule::strict, StabilityRule::horizon};

class Cover {
public:
    // `taken` counts the samples against the limit: this cover's own unless told.
    Cover(const Kernel& kernel, const Lattice& lattice, const CoverModel& model,
          const std::function<StabilitySample(double)>& at, std::function<int()> taken = {})
        : kernel_(kernel), lattice_(lattice), model_(model), at_(at), taken_(std::move(taken)),
          reciprocal_(reciprocal_lattice(lattice))
    {
    }

    // Halves [a, b] until each part is settled or no wider than the tolerance.
    void refine(double a, double b)
    {
        const StabilitySample& sa = sample(a);
        const StabilitySample& sb = sample(b);
        if (b - a <= stability_k_tolerance) return;
        if (agree(sa, sb)) {
            if (covered(sa, sb)) return;
            // Past the limit only changes of verdict are still looked for.
            if ((taken_ ? taken_() : static_cast<int>(seen_.size())) >= cover_sample_limit) return void(certain_ = false);
        }
        const double m = 0.5 * (a + b);
        refine(a, m);
        refine(m, b);
    }

    std::vector<StabilitySample> looked_at() const
    {
        std::vector<StabilitySample> all;
        for (const auto& [k, s] : seen_) all.push_back(s);
        return all;
    }
    bool certain() const { return certain_; }

private:
    const StabilitySample& sample(double k)
    {
        if (auto found = seen_.find(k); found != seen_.end()) return found->second;
        return seen_.emplace(k, at_(k)).first->second;
    }

    static bool agree(const StabilitySample& a, const StabilitySample& b)
    {
        return std::all_of(std::begin(rules), std::end(rules),
                           [&](StabilityRule r) { return rule_holds(a, r) == rule_holds(b, r); });
    }

    // Whether no change of verdict can lie between the two ends, under every rule.
    bool covered(const StabilitySample& a, const StabilitySample& b)
    {
        const CellRates r{rates(a.k), rates(0.5 * (a.k + b.k)), rates(b.k)};
        return std::all_of(std::begin(rules), std::end(rules),
                           [&](StabilityRule rule) { return verdict_spans(rule, a, b, r, model_.horizon); });
    }

    const KChangeRates& rates(double k)
    {
        if (auto found = rates_.find(k); found != rates_.end()) return found->second;
        // The grid's orbits are found once, from the spectrum's symmetries at the first k asked.
        if (!grid_) grid_.emplace(Dispersion(kernel_, lattice_, k, model_.gamma, model_.h_model), reciprocal_, model_.grid);
        return rates_.try_emplace(k, kernel_, lattice_, *grid_, k, model_.gamma, model_.h_model).first->second;
    }

    const Kernel& kernel_;
    const Lattice& lattice_;
    const CoverModel& model_;
    const std::function<StabilitySample(double)>& at_;
    const std::function<int()> taken_;
    const ReciprocalLattice reciprocal_;
    std::map<double, StabilitySample> seen_;
    std::optional<RateGrid> grid_;
    std::map<double, KChangeRates> rates_;
    bool certain_ = true;
};

// The cells' ends: an even grid no coarser than cover_cell_width, and both sides of each
// jump of the dispersion matrix (the shell just outside the support, and on its edge).
std::vector<double> cell_ends(const Kernel& kernel, const Lattice& lattice, double k_min, double k_max)
{
    const int cells = std::max(1, static_cast<int>(std::ceil((k_max - k_min) / cover_cell_width)));
    std::vector<double> ends;
    for (int i = 0; i <= cells; ++i) ends.push_back(i == cells ? k_max : k_min + (k_max - k_min) * i / cells);
    for (double k : dispersion_jumps(kernel, lattice, k_min, k_max)) {
        if (k * (1 - 1e-9) > k_min) ends.push_back(k * (1 - 1e-9));
        ends.push_back(k);
    }
    std::sort(ends.begin(), ends.end());
    ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
    return ends;
}

// The intervals where the rule holds over points sorted by k; a change between two
// neighbours (no farther apart than the tolerance) lies midway.
std::vector<KInterval> intervals_of(const std::vector<StabilitySample>& points, StabilityRule rule)
{
    std::vector<KInterval> found;
    bool inside = false;
    double start = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const bool holds = rule_holds(points[i], rule);
        const double edge = i == 0 ? points[i].k : 0.5 * (points[i - 1].k + points[i].k);
        if (holds && !inside) start = edge, inside = true;
        if (!holds && inside) found.push_back({start, edge}), inside = false;
    }
    if (inside) found.push_back({start, points.back().k});
    return found;
}

} // namespace

void prefetch_cover(const Kernel& kernel, const Lattice& lattice, double k_min, double k_max, const CoverModel& model,
                    const std::function<StabilitySample(double)>& at, int threads)
{
    const auto ends = cell_ends(kernel, lattice, k_min, k_max);
    // The cells' ends first, then each cell's halving on its own (the cover's own rates grid
    // may differ, and the sample limit is shared loosely: this only guesses what it will ask).
    std::atomic<int> taken{0};
    const std::function<StabilitySample(double)> counted = [&](double k) {
        taken.fetch_add(1, std::memory_order_relaxed);
        return at(k);
    };
    // A k refused here may be one the cover never asks for: it asks again itself if it does.
    auto guessing = [](const auto& work) {
        try {
            work();
        } catch (const Error& e) {
            if (e.code() == ExitCode::interrupted) throw;
        }
    };
    ParallelFor ends_pass;
    ends_pass.run_blocks(ends.size(), 1, threads,
                         [&](std::size_t i, std::size_t, std::size_t) { guessing([&] { counted(ends[i]); }); });
    ParallelFor cells_pass;
    cells_pass.run_blocks(ends.size() - 1, 1, threads, [&](std::size_t i, std::size_t, std::size_t) {
        Cover cell(kernel, lattice, model, counted, [&] { return taken.load(std::memory_order_relaxed); });
        guessing([&] { cell.refine(ends[i], ends[i + 1]); });
    });
}

VerdictCover cover_verdicts(const Kernel& kernel, const Lattice& lattice, double k_min, double k_max,
                            const CoverModel& model, const std::function<StabilitySample(double)>& at)
{
    Cover cover(kernel, lattice, model, at);
    const auto ends = cell_ends(kernel, lattice, k_min, k_max);
    if (ends.size() == 1) cover.refine(k_min, k_min);
    for (std::size_t i = 0; i + 1 < ends.size(); ++i) cover.refine(ends[i], ends[i + 1]);
    VerdictCover result;
    result.looked_at = cover.looked_at();
    result.certain = cover.certain();
    if (!result.certain)
        spdlog::warn("stability over k: {} samples taken and some stretches of k are still not settled; a stable "
                     "window narrower than them may be missed", cover_sample_limit);
    result.stable = intervals_of(result.looked_at, StabilityRule::strict);
    result.usable = intervals_of(result.looked_at, StabilityRule::horizon);
    return result;
}

} // namespace sphkern
