#include "particles/density_smoothing.hpp"

#include "kernels/kernel_validity.hpp"
#include "particles/engine/lane_sums.hpp"
#include "particles/engine/neighbour_gather.hpp"
#include "particles/engine/neighbour_grid.hpp"
#include "particles/engine/pair_pass.hpp"
#include "support/error.hpp"
#include "support/process/parallel_for.hpp"
#include "support/vector_clones.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <vector>

namespace sphkern {

namespace {

// sum_j m_j w(q_j) and sum_j m_j q_j w'(q_j) over the neighbours with r2_j <= reach2 (those a
// search within sqrt(reach2) keeps), in lanes (lane_sums.hpp); n is a multiple of them.
SPHKERN_ENGINE_CLONES void weighted_sums(const double* w_, const double* dw_, const double* q_, const double* m_,
                                         const double* r2_, std::size_t n, double reach2, double& mw, double& mqdw)
{
    const UnalignedQuad *w = as_quads(w_), *dw = as_quads(dw_), *q = as_quads(q_), *m = as_quads(m_),
                        *r2 = as_quads(r2_);
    const Quad reach = {reach2, reach2, reach2, reach2}, zero = {};
    Partial a, b;
    for (std::size_t i = 0; i < n / 4; ++i) {
        const Quad mi = r2[i] <= reach ? m[i] : zero;
        a.add(i, mi * w[i]), b.add(i, mi * q[i] * dw[i]);
    }
    mw = a.total(), mqdw = b.total();
}

// r = sqrt(r2) of n entries.
SPHKERN_ENGINE_CLONES void roots_of(const double* __restrict r2, double* __restrict r, std::size_t n)
{
    for (std::size_t j = 0; j < n; ++j) r[j] = std::sqrt(r2[j]);
}

// The particle itself as one more entry at r = 0 with its mass (times the code's weight of
// its own term), so that its W(0) is one more lane of the batch; the padding after it zero.
void add_self(Neighbours& nb, double mass)
{
    const std::size_t s = nb.count++;
    nb.reserve(padded_count(nb.count));
    for (std::size_t j = s; j < padded_count(nb.count); ++j) nb.r2[j] = nb.r[j] = nb.a[j] = 0;
    nb.a[s] = mass;
}

// Keeps the neighbours with r2 <= reach2, in their order, padded as the gather pads (mass 0);
// with `slots`, each one's place in the gathered list (nb.slot) too, where a measure finds its
// dx, dy, dz and b.
void keep_within(Neighbours& nb, double reach2, bool slots)
{
    std::size_t kept = 0;
    for (std::size_t j = 0; j < nb.count; ++j) { // written at `kept` whether kept or not: no branch to mispredict
        const double r2 = nb.r2[j], r = nb.r[j], a = nb.a[j], slot = nb.slot[j];
        nb.r2[kept] = r2, nb.r[kept] = r, nb.a[kept] = a;
        if (slots) nb.slot[kept] = slot;
        kept += r2 <= reach2;
    }
    nb.count = kept;
    for (std::size_t j = kept; j < padded_count(kept); ++j) nb.r2[j] = nb.r[j] = nb.a[j] = 0;
}

// The measures' neighbours of a particle solved at h from its solve's list (r2, m_j in a, W
// and W' at h in w and dw, itself last; dx, dy, dz and V_j in b at their places in the
// gathered list, nb.slot): those inside h's search reach but itself, in their order, with
// V_j in a and m_j in b as the measures read them, and the padding zero. A place is never
// before the entry's own index, so the arrays are compacted in place.
std::size_t measured_neighbours(Neighbours& nb, double reach2)
{
    std::size_t kept = 0;
    for (std::size_t j = 0; j + 1 < nb.count; ++j) { // written at `kept` whether kept or not
        const auto from = static_cast<std::size_t>(nb.slot[j]);
        const double mass = nb.a[j], volume = nb.b[from], w = nb.w[j], dw = nb.dw[j];
        const double dx = nb.dx[from], dy = nb.dy[from], dz = nb.dz[from];
        nb.dx[kept] = dx, nb.dy[kept] = dy, nb.dz[kept] = dz, nb.w[kept] = w, nb.dw[kept] = dw;
        nb.a[kept] = volume, nb.b[kept] = mass;
        kept += nb.r2[j] <= reach2;
    }
    for (std::size_t j = kept; j < padded_count(kept); ++j)
        nb.dx[j] = nb.dy[j] = nb.dz[j] = nb.a[j] = nb.b[j] = nb.w[j] = nb.dw[j] = 0;
    nb.count = kept;
    return kept;
}

// How far a pass's solve got: the largest relative residual at the particles' last
// evaluation, and how many particles a next pass must take up.
struct PassProgress {
    double residual = 0;
    std::size_t left = 0, unsettled = 0; // unsettled: out of Newton steps
};

// A particle's next h from its density at h, its relative residual there, and whether h is its solution.
struct NewtonStep {
    double next, residual;
    bool solved;
};

// Each pass gathers the neighbours within the support of this many times a particle's h:
// wider costs every particle's search and sums its margin to the power D, narrower sends more
// particles to a second pass (the first pass's wider margin of 1.15 was slower: BENCHMARKS.md).
constexpr double allowance = 1.1;
// Below this relative residual a particle's list is cut to near_margin times its next h.
constexpr double near_root = 5e-2, near_margin = 1.08;

// Each particle's h from its own density: rho_i = sum_j m_j W(r_ij, h_i) with itself, and its
// derivative in h_i. In the gather form a particle's density depends on its own h alone, so a
// pass gathers each unsolved particle's neighbours once, within the support of `allowance`
// times its h, and takes its Newton steps on that list while h stays inside it; a particle
// whose step leaves it is taken up by the next pass, from where the step led. The neighbours
// farther than an h's own search reach are left out of that h's sums (their mass counted as
// zero), so each sum has the terms a search at that h would give (added in lanes: the last
// bits are the list's, the same on any number of threads). With a MeasureCollector, a particle
// is measured as it is solved, over its neighbours within its h's reach, with the W and W' of
// the evaluation that solved it.
class DensityPass {
public:
    DensityPass(const Kernel& kernel, const ParticleSet& set, std::span<const double> mass, double spacing,
                double self_weight, int threads, MeasureCollector* measures)
        : kernel_(kernel), set_(set), mass_(mass), spacing_(spacing), self_weight_(self_weight), threads_(threads),
          measures_(measures), steps_(set.size(), 0)
    {}

    // Newton steps for the particles whose `solving` is set; `step(m, h, rho, drho)` gives the NewtonStep of a particle
    // of mass m.
    template <class Step>
    PassProgress operator()(std::span<double> h, std::vector<std::uint8_t>& solving, double wanted_allowance,
                            const Step& step)
    {
        const double h_largest = *std::max_element(h.begin(), h.end());
        // A periodic box holds a search of at most half its width (with the grid's margin of 1.1):
        // the margin shrinks to fit, down to none, where the box then refuses h itself as before.
        const double widest = set_.box ? set_.box->smallest_width(set_.dimension) / 2 : INFINITY;
        const double allowance =
            std::max(1.0, std::min(wanted_allowance, widest / (1.1 * kernel_.support() * h_largest)));
        const double h_max = allowance * h_largest;
        require_usable_kernel(kernel_, set_.dimension, h_max / spacing_);
        // The grid is kept while every support fits it: the solve moves h by little after its first pass.
        if (!grid_ || kernel_.support() * h_max > grid_reach_) {
            grid_reach_ = 1.1 * kernel_.support() * h_max;
            grid_.emplace(set_, grid_reach_, threads_);
            mass_points_ = grid_->gather(mass_);
            if (measures_ && measures_->volumes_differ()) volume_points_ = grid_->gather(measures_->volumes());
        }
        const NeighbourGrid& grid = *grid_;
        const std::vector<double> h_points = grid.gather(h);
        std::vector<double> reach(h_points.size());
        std::vector<std::uint8_t> only(h_points.size());
        for (std::size_t p = 0; p < reach.size(); ++p) {
            reach[p] = search_reach(kernel_.support() * allowance * h_points[p]);
            only[p] = grid.visited(p) && solving[grid.source(p)];
        }
        std::vector<PassProgress> per_thread(static_cast<std::size_t>(std::max(1, threads_)));
        const double* volumes = volume_points_.empty() ? nullptr : volume_points_.data();
        const PairPassInputs in{{reach.data(), 0}, mass_points_.data(), volumes, true, "", only.data()};
        pair_pass(
            grid, set_.name, in, threads_,
            [&](int thread, std::size_t p, Neighbours& nb) {
                const std::size_t i = grid.source(p);
                const Outcome o = solve(thread, nb, p, i, h_points[p], allowance * h_points[p], step);
                PassProgress& progress = per_thread[static_cast<std::size_t>(thread)];
                progress.residual = std::max(progress.residual, o.residual);
                progress.left += o.end == End::beyond, progress.unsettled += o.end == End::unsettled;
                solving[i] = o.end != End::solved, h[i] = o.h, steps_[i] = static_cast<std::uint8_t>(o.steps);
            },
            [](int) {});
        PassProgress total;
        for (const PassProgress& t : per_thread)
            total.residual = std::max(total.residual, t.residual), total.left += t.left, total.unsettled += t.unsettled;
        return total;
    }

    static constexpr int max_steps = 100; // a particle's Newton steps over all passes

private:
    enum class End { solved, beyond, unsettled };
    struct Outcome {
        End end;
        double h, residual; // solved: its h; beyond: where its next pass starts; unsettled: its last h
        int steps;          // Newton steps taken, this pass's and the earlier ones'
    };

    // Point p's (particle i's) Newton steps from h over its neighbours nb, while h stays at most
    // h_top; nb holds the neighbours within the support of h_top.
    template <class Step>
    Outcome solve(int thread, Neighbours& nb, std::size_t p, std::size_t i, double h, double h_top,
                  const Step& step) const
    {
        roots_of(nb.r2.data(), nb.r.data(), padded_count(nb.count));
        if (measures_)
            for (std::size_t j = 0; j < nb.count; ++j) nb.slot[j] = static_cast<double>(j);
        add_self(nb, self_weight_ * mass_points_[p]);
        bool cut = false;
        for (int taken = steps_[i];;) {
            const auto [rho, drho] = density_at(nb, i, h);
            const NewtonStep s = step(mass_points_[p], h, rho, drho);
            if (s.solved) {
                if (measures_) { // W and W' are this h's where the kernel's k is the measures'
                    const double reach = search_reach(kernel_.support() * h);
                    measures_->measure(thread, i, h, measured_neighbours(nb, reach * reach), nb,
                                       measures_->spacing() == spacing_);
                }
                return {End::solved, h, s.residual, taken};
            }
            if (++taken == max_steps) return {End::unsettled, h, s.residual, taken};
            if (s.next > h_top) return {End::beyond, s.next, s.residual, taken}; // beyond the neighbours gathered
            // Near its root a particle's steps stay close: the neighbours beyond a margin of
            // the next h are dropped, once (a step past it goes to the next pass).
            if (!cut && s.residual < near_root && s.next * near_margin < h_top) {
                h_top = s.next * near_margin, cut = true;
                const double top_reach = search_reach(kernel_.support() * h_top);
                keep_within(nb, top_reach * top_reach, measures_ != nullptr);
            }
            h = s.next;
        }
    }

    // rho_i(h) and drho_i / dh over the neighbours in nb within h's search reach.
    std::pair<double, double> density_at(Neighbours& nb, std::size_t i, double h) const
    {
        const int dim = set_.dimension;
        const std::size_t n = padded_count(nb.count);
        const double k = h / spacing_, reach = search_reach(kernel_.support() * h);
        scale_distances(nb.r.data(), n, 1 / h, nb.q.data());
        kernel_.w_dw_batch(nb.q.data(), nb.w.data(), nb.dw.data(), n, dim, k);
        double mw = 0, mqdw = 0;
        weighted_sums(nb.w.data(), nb.dw.data(), nb.q.data(), nb.a.data(), nb.r2.data(), n, reach * reach, mw, mqdw);
        const double hd = dim == 3 ? h * h * h : h * h;
        // W = w(q) / h^D: dW / dh = -(D w + q w') / h^(D+1).
        const double rho = mw / hd, drho = -(dim * mw + mqdw) / (hd * h);
        if (!std::isfinite(rho) || !std::isfinite(drho))
            fail_non_finite_sum(kernel_, dim, k, fmt::format("particle {} of {}", i, set_.name),
                                fmt::format("h = {:.6g}", h), {nb.q.data(), nb.count});
        return {rho, drho};
    }

    const Kernel& kernel_;
    const ParticleSet& set_;
    std::span<const double> mass_;
    double spacing_, self_weight_;
    int threads_;
    MeasureCollector* measures_;
    std::optional<NeighbourGrid> grid_;
    double grid_reach_ = 0;
    std::vector<double> mass_points_, volume_points_; // volumes: where a collector reads them per neighbour
    std::vector<std::uint8_t> steps_;                 // Newton steps taken per particle
};

} // namespace

PerParticle density_smoothing_lengths(const Kernel& kernel, const ParticleSet& set, double coefficient,
                                      double mean_volume, int threads, bool by_number, double self_weight,
                                      MeasureCollector* measures)
{
    if (set.neighbours_only > 0)
        fail_input(
            fmt::format("{}: h from the SPH density is solved for every particle; the set has {} neighbours-only "
                        "particles, expected one particle array",
                        set.name, set.neighbours_only));
    const int dim = set.dimension;
    const std::size_t n = set.size();
    // Without masses, or counting by number, every particle has the mean volume's (rho0 = 1).
    const bool equal = by_number || set.mass.size() != n;
    const std::vector<double> own_masses = equal ? std::vector<double>(n, mean_volume) : std::vector<double>();
    const std::span<const double> masses = own_masses.empty() ? std::span<const double>(set.mass) : own_masses;
    auto mass = [&](std::size_t i) { return masses[i]; };
    // c (m / rho)^(1/D), by cbrt and sqrt: pow took a tenth of the solve.
    auto h_of = [&](double m, double rho) {
        const double v = m / rho;
        return coefficient * (dim == 3 ? std::cbrt(v) : dim == 2 ? std::sqrt(v) : v);
    };
    // Each particle's residual g(h) = h - c (m / rho(h))^(1/D) vanishes at its h, found by
    // Newton steps on g (g' from drho / dh, as SWIFT and GADGET step), a step that leaves
    // [h / 2, 2 h] or a g' that is not positive falling back to the fixed point's step. A
    // particle is done once its own residual is below the tolerance, at the h it was measured at.
    // The first guess takes the set's mean density, whatever the masses' units.
    double total_mass = 0;
    for (std::size_t i = 0; i < n; ++i) total_mass += mass(i);
    const double mean_density = total_mass / (static_cast<double>(n) * mean_volume);
    PerParticle h =
        PerParticle::of(fill_particle_values(n, threads, [&](std::size_t i) { return h_of(mass(i), mean_density); }));
    std::vector<std::uint8_t> solving(n, 1);
    if (measures && measures->with_mass() && equal)
        throw std::logic_error("density_smoothing_lengths: the measures' masses are not the solve's");
    DensityPass densities(kernel, set, masses, std::pow(mean_volume, 1.0 / dim), self_weight, threads, measures);
    constexpr double tolerance = 1e-12;
    const auto step = [&](double m, double now, double rho, double drho) {
        const double fixed = h_of(m, rho), g = now - fixed;
        if (std::abs(g) <= tolerance * now) return NewtonStep{now, std::abs(g) / now, true};
        const double slope = 1 + fixed / dim * drho / rho, newton = now - g / slope;
        return NewtonStep{slope > 0 && newton > 0.5 * now && newton < 2 * now ? newton : fixed, std::abs(g) / now,
                          false};
    };
    for (int pass = 1;; ++pass) {
        const PassProgress progress = densities(std::span<double>(h.values.data(), n), solving, allowance, step);
        spdlog::debug("h from the SPH density: pass {}, largest relative residual {:.3g}, {} particles left", pass,
                      progress.residual, progress.left);
        if (progress.unsettled > 0)
            fail_input(
                fmt::format("{}: h from the SPH density did not settle in {} Newton steps for {} particles (the "
                            "largest relative residual is still {:.3g}); expected a set whose density the kernel "
                            "resolves",
                            set.name, DensityPass::max_steps, progress.unsettled, progress.residual));
        if (progress.left == 0) return h;
    }
}

} // namespace sphkern
