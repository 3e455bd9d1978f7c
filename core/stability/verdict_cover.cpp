#include "stability/verdict_cover.hpp"

#include "stability/brillouin_zone.hpp"
#include "stability/dispersion_jumps.hpp"
#include "stability/verdict_span.hpp"
#include "support/error.hpp"
#include "support/process/parallel_for.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <utility>

namespace sphkern {

struct CoverRates {
    std::optional<RateGrid> grid;
    std::map<double, std::shared_ptr<const KChangeRates>> at;
};

namespace {

constexpr StabilityRule rules[] = {StabilityRule::strict, StabilityRule::horizon};

bool agree(const StabilitySample& a, const StabilitySample& b)
{
    return std::all_of(std::begin(rules), std::end(rules),
                       [&](StabilityRule r) { return rule_holds(a, r) == rule_holds(b, r); });
}

// Whether no change of verdict can lie between the two ends, under every rule.
bool covered(const StabilitySample& a, const StabilitySample& b, const CellRates& rates, double horizon)
{
    return std::all_of(std::begin(rules), std::end(rules),
                       [&](StabilityRule rule) { return verdict_spans(rule, a, b, rates, horizon); });
}

bool same_grid(const RateGrid& a, const RateGrid& b)
{
    if (a.size() != b.size() || a.points() != b.points()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a.kappa(i) != b.kappa(i)) return false;
    return true;
}

class Cover {
public:
    // `known`: rates measured before, used where they were measured on this cover's own grid.
    Cover(const Kernel& kernel, const Lattice& lattice, const CoverModel& model,
          const std::function<StabilitySample(double)>& at, const CoverRates* known)
        : kernel_(kernel), lattice_(lattice), model_(model), at_(at), known_(known),
          reciprocal_(reciprocal_lattice(lattice))
    {}

    // Halves [a, b] until each part is settled or no wider than the tolerance.
    void refine(double a, double b)
    {
        const StabilitySample& sa = sample(a);
        const StabilitySample& sb = sample(b);
        if (b - a <= stability_k_tolerance) return;
        if (agree(sa, sb)) {
            if (covered(sa, sb, {rates(sa.k), rates(0.5 * (sa.k + sb.k)), rates(sb.k)}, model_.horizon)) return;
            // Past the limit only changes of verdict are still looked for.
            if (static_cast<int>(seen_.size()) >= cover_sample_limit) return void(certain_ = false);
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

    const KChangeRates& rates(double k)
    {
        if (auto found = rates_.find(k); found != rates_.end()) return *found->second;
        // The grid's orbits are found once, from the spectrum's symmetries at the first k asked.
        if (!grid_) {
            grid_.emplace(Dispersion(kernel_, lattice_, k, model_.gamma, model_.h_model), reciprocal_, model_.grid);
            shared_ = known_ && known_->grid && same_grid(*known_->grid, *grid_);
        }
        if (shared_) {
            const auto found = known_->at.find(k);
            if (found != known_->at.end()) return *rates_.emplace(k, found->second).first->second;
        }
        auto made = std::make_shared<const KChangeRates>(kernel_, lattice_, *grid_, k, model_.gamma, model_.h_model);
        return *rates_.emplace(k, std::move(made)).first->second;
    }

    const Kernel& kernel_;
    const Lattice& lattice_;
    const CoverModel& model_;
    const std::function<StabilitySample(double)>& at_;
    const CoverRates* known_;
    const ReciprocalLattice reciprocal_;
    std::map<double, StabilitySample> seen_;
    std::optional<RateGrid> grid_;
    bool shared_ = false; // known_'s rates are on grid_
    std::map<double, std::shared_ptr<const KChangeRates>> rates_;
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

// make(k) for every k, side by side on `threads` threads; empty where it was refused (a k the
// cover may never ask for: it asks again itself if it does).
template <class T, class Make>
std::vector<std::optional<T>> side_by_side(const std::vector<double>& ks, int threads, const Make& make)
{
    std::vector<std::optional<T>> made(ks.size());
    ParallelFor pass;
    pass.run_blocks(ks.size(), 1, threads, [&](std::size_t i, std::size_t, std::size_t) {
        try {
            made[i] = make(ks[i]);
        } catch (const Error& e) {
            if (e.code() == ExitCode::interrupted) throw;
        }
    });
    return made;
}

std::vector<double> sorted_unique(std::vector<double> ks)
{
    std::sort(ks.begin(), ks.end());
    ks.erase(std::unique(ks.begin(), ks.end()), ks.end());
    return ks;
}

// The rates at the ends and the middle of each agreeing interval, those not yet known, side by side.
void measure_rates(CoverRates& rates, const std::vector<std::pair<double, double>>& agreeing, const Kernel& kernel,
                   const Lattice& lattice, const CoverModel& model, int threads)
{
    std::vector<double> needed;
    for (const auto& [a, b] : agreeing)
        for (double k : {a, 0.5 * (a + b), b})
            if (!rates.at.count(k)) needed.push_back(k);
    needed = sorted_unique(std::move(needed));
    const auto measured = side_by_side<std::shared_ptr<const KChangeRates>>(needed, threads, [&](double k) {
        return std::make_shared<const KChangeRates>(kernel, lattice, *rates.grid, k, model.gamma, model.h_model);
    });
    for (std::size_t i = 0; i < needed.size(); ++i)
        if (measured[i]) rates.at.emplace(needed[i], *measured[i]);
}

} // namespace

std::shared_ptr<const CoverRates> prefetch_cover(const Kernel& kernel, const Lattice& lattice, double k_min,
                                                 double k_max, const CoverModel& model,
                                                 const std::function<StabilitySample(double)>& at, int threads)
{
    auto rates = std::make_shared<CoverRates>();
    const auto ends = cell_ends(kernel, lattice, k_min, k_max);
    try {
        rates->grid.emplace(Dispersion(kernel, lattice, k_min, model.gamma, model.h_model), reciprocal_lattice(lattice),
                            model.grid);
    } catch (const Error& e) {
        if (e.code() == ExitCode::interrupted) throw;
    }
    // Every cell halved as the cover halves it, a round at a time: each round's samples, then
    // the rates its agreeing intervals need, side by side.
    std::vector<std::pair<double, double>> round;
    for (std::size_t i = 0; i + 1 < ends.size(); ++i) round.emplace_back(ends[i], ends[i + 1]);
    std::map<double, StabilitySample> known;
    if (ends.size() == 1) known.emplace(ends[0], at(ends[0]));
    int taken = 0, rounds = 0;
    for (; !round.empty(); ++rounds) {
        std::vector<double> wanted;
        for (const auto& [a, b] : round)
            for (double k : {a, b})
                if (!known.count(k)) wanted.push_back(k);
        wanted = sorted_unique(std::move(wanted));
        const auto samples = side_by_side<StabilitySample>(wanted, threads, at);
        for (std::size_t i = 0; i < wanted.size(); ++i)
            if (samples[i]) known.emplace(wanted[i], *samples[i]);
        taken += static_cast<int>(wanted.size());
        std::vector<std::pair<double, double>> next, agreeing;
        auto halve = [&](double a, double b) {
            next.emplace_back(a, 0.5 * (a + b));
            next.emplace_back(0.5 * (a + b), b);
        };
        for (const auto& [a, b] : round) {
            if (!known.count(a) || !known.count(b) || b - a <= stability_k_tolerance) continue;
            if (agree(known.at(a), known.at(b))) agreeing.emplace_back(a, b);
            else halve(a, b);
        }
        if (rates->grid) {
            measure_rates(*rates, agreeing, kernel, lattice, model, threads);
            for (const auto& [a, b] : agreeing) {
                const double m = 0.5 * (a + b);
                if (!rates->at.count(a) || !rates->at.count(m) || !rates->at.count(b)) continue;
                const CellRates r{*rates->at.at(a), *rates->at.at(m), *rates->at.at(b)};
                if (!covered(known.at(a), known.at(b), r, model.horizon) && taken < cover_sample_limit) halve(a, b);
            }
        }
        round = std::move(next);
    }
    spdlog::debug("stability over k: {} samples and {} rates taken ahead in {} rounds{}", known.size(),
                  rates->at.size(), rounds, rates->grid ? "" : " (no rate grid)");
    return rates;
}

VerdictCover cover_verdicts(const Kernel& kernel, const Lattice& lattice, double k_min, double k_max,
                            const CoverModel& model, const std::function<StabilitySample(double)>& at,
                            const CoverRates* known)
{
    Cover cover(kernel, lattice, model, at, known);
    const auto ends = cell_ends(kernel, lattice, k_min, k_max);
    if (ends.size() == 1) cover.refine(k_min, k_min);
    for (std::size_t i = 0; i + 1 < ends.size(); ++i) cover.refine(ends[i], ends[i + 1]);
    VerdictCover result;
    result.looked_at = cover.looked_at();
    result.certain = cover.certain();
    if (!result.certain)
        spdlog::warn("stability over k: {} samples taken and some stretches of k are still not settled; a stable "
                     "window narrower than them may be missed",
                     cover_sample_limit);
    result.stable = intervals_of(result.looked_at, StabilityRule::strict);
    result.usable = intervals_of(result.looked_at, StabilityRule::horizon);
    return result;
}

} // namespace sphkern
