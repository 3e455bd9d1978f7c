#include "relax/relaxation.hpp"

#include "particles/engine/neighbour_gather.hpp"
#include "support/text/setting_names.hpp"

#include "support/error.hpp"
#include "support/process/interruption.hpp"
#include "support/process/parallel_for.hpp"
#include "support/process/progress.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <optional>

namespace sphkern {

double length_unit(const ParticleSet& set)
{
    if (set.spacing > 0) return set.spacing;
    return mean_spacing(set);
}

namespace {

// The skin of the forces' pair list, in h: the fastest of 0.1, 0.2, 0.3 and 0.5 on the pairing
// runs and relaxations measured (BENCHMARKS.md, "Pair lists that last").
constexpr double pair_list_skin = 0.2;

// RMS e0 and |e1| of the sums just computed (block sums: the same on any thread count).
void record_errors(const RelaxState& s, RelaxStep& step)
{
    const std::size_t n = s.set.size();
    const auto& f = s.forces;
    using Sums = std::array<double, 2>; // e0^2 and |e1|^2, in one pass
    const Sums sums = parallel_reduce(
        n, s.model.threads, Sums{0, 0},
        [&](std::size_t i, Sums& a) {
            const double d = f.density[i] / s.model.mass * s.model.volume - 1;
            a[0] += d * d;
            a[1] += (f.gx[i] * f.gx[i] + f.gy[i] * f.gy[i] + f.gz[i] * f.gz[i]) * s.model.h * s.model.h;
        },
        [](Sums& total, const Sums& block) { total[0] += block[0], total[1] += block[1]; });
    step.rms_e0 = std::sqrt(sums[0] / static_cast<double>(n));
    step.rms_e1 = std::sqrt(sums[1] / static_cast<double>(n));
}

// Moves particle i by (dx, dy, dz) and returns the squared length of the move.
double move(RelaxState& s, std::size_t i, double dx, double dy, double dz)
{
    s.set.x[i] += dx, s.set.y[i] += dy;
    s.ux[i] += dx, s.uy[i] += dy;
    if (s.set.dimension == 3) s.set.z[i] += dz, s.uz[i] += dz;
    return dx * dx + dy * dy + (s.set.dimension == 3 ? dz * dz : 0.0);
}

// The sum and the largest of the squared moves of a step.
struct Moves {
    double sum2 = 0, max2 = 0;
};

// Moves every particle by move_of(i) (an Eigen::Vector3d), in parallel.
template <class MoveOf>
Moves move_all(RelaxState& s, const MoveOf& move_of)
{
    return parallel_reduce(
        s.set.size(), s.model.threads, Moves{},
        [&](std::size_t i, Moves& m) {
            const Eigen::Vector3d d = move_of(i);
            const double m2 = move(s, i, d.x(), d.y(), d.z());
            m.sum2 += m2, m.max2 = std::max(m.max2, m2);
        },
        [](Moves& total, const Moves& block) {
            total.sum2 += block.sum2, total.max2 = std::max(total.max2, block.max2);
        });
}

// False when the integration diverges: a move that is not finite, or longer than a quarter of
// the box in one step, is no relaxation (and would be taken for a particle outside the box).
bool finish_moves(RelaxState& s, RelaxStep& step, const Moves& moves)
{
    step.rms_move = std::sqrt(moves.sum2 / static_cast<double>(s.set.size())) / s.model.h;
    step.max_move = std::sqrt(moves.max2) / s.model.h;
    if (!std::isfinite(moves.sum2) || !(std::sqrt(moves.max2) <= s.set.box->smallest_width(s.set.dimension) / 4))
        return false;
    wrap_into_box(s.set, WrapReach::one_box, s.model.threads);
    return true;
}

[[noreturn]] void fail_diverged(const RelaxState& s, const RelaxSettings& settings, const RelaxStep& step, double dt,
                                std::vector<RelaxStep> history)
{
    const std::string move = std::isfinite(step.max_move)
                                 ? fmt::format("a particle moved {:.3g} h in one step", step.max_move)
                                 : std::string("a particle's move in one step overflowed a double");
    throw RelaxDiverged(fmt::format("{}: the integration diverged at step {} (t = {:.4g} d/c): {}; expected a smaller "
                                    "{} (now {:g}), more {} (now {:g}) or a {} nearer 1 (now {:g})",
                                    s.set.name, step.step, step.step * dt, move, setting_named("dt"),
                                    settings.time_step, setting_named("damping"), settings.damping,
                                    setting_named("gamma"), settings.gamma),
                        std::move(history));
}

// Kick (exact damping over half a step, then the force), used twice a step: no sum, so in
// blocks small enough to keep 16 threads busy on 10^5 particles.
void kick(RelaxState& s, double half_dt, double damping_factor)
{
    const bool three = s.set.dimension == 3;
    ParallelFor pass;
    pass.run_blocks(s.set.size(), 2048, s.model.threads, [&](std::size_t, std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            s.vx[i] = s.vx[i] * damping_factor + s.forces.ax[i] * half_dt;
            s.vy[i] = s.vy[i] * damping_factor + s.forces.ay[i] * half_dt;
            s.vz[i] = three ? s.vz[i] * damping_factor + s.forces.az[i] * half_dt : 0.0;
        }
    });
}

// False when the integration diverges (finish_moves).
bool pressure_step(const Kernel& kernel, RelaxState& s, double dt, double damping, RelaxStep& step)
{
    const double factor = std::exp(-damping * dt / 2);
    kick(s, dt / 2, factor);
    const Moves moves =
        move_all(s, [&](std::size_t i) { return Eigen::Vector3d(s.vx[i] * dt, s.vy[i] * dt, s.vz[i] * dt); });
    if (!finish_moves(s, step, moves)) return false;
    compute_forces(kernel, s.set, s.model, s.forces, &s.pairs);
    kick(s, dt / 2, factor);
    const double kinetic = parallel_sum(s.set.size(), s.model.threads, [&](std::size_t i) {
        return s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i] + s.vz[i] * s.vz[i];
    });
    step.kinetic = kinetic / 2 / static_cast<double>(s.set.size()) / (s.model.c * s.model.c);
    return true;
}

// dx_i = -alpha h^2 sum_j V grad_i W_ij, shortened to max_move h where it is longer.
bool shift_step(const Kernel& kernel, RelaxState& s, const RelaxSettings& settings, RelaxStep& step)
{
    const double h = s.model.h, limit = settings.max_move * h;
    const Moves moves = move_all(s, [&](std::size_t i) {
        Eigen::Vector3d d = -settings.alpha * h * h * Eigen::Vector3d(s.forces.gx[i], s.forces.gy[i], s.forces.gz[i]);
        const double length = d.norm();
        if (length > limit) d *= limit / length;
        return d;
    });
    if (!finish_moves(s, step, moves)) return false;
    compute_forces(kernel, s.set, s.model, s.forces, &s.pairs);
    return true;
}

RelaxState start_state(const Kernel& kernel, ParticleSet set, double h, const RelaxSettings& settings, double d)
{
    RelaxState s;
    const std::size_t n = set.size();
    const int dim = set.dimension;
    s.model.h = h;
    s.model.volume = set.box->volume(dim) / static_cast<double>(n);
    s.model.mass = s.model.volume; // unit reference density: results do not depend on it
    s.model.c = d;                 // one d per unit time: times come out in d / c
    s.model.gamma = settings.gamma;
    s.model.k = h / d;
    s.model.pressure = settings.method == RelaxMethod::pressure;
    s.model.threads = worker_threads(settings.threads);
    s.model.skin = pair_list_skin;
    s.set = std::move(set);
    // rho0: the mean SPH density of the start, where P / rho = c^2 / gamma (on a lattice, every particle's).
    ForceModel density_only = s.model;
    density_only.pressure = false;
    compute_forces(kernel, s.set, density_only, s.forces, &s.pairs);
    const double total = parallel_sum(n, s.model.threads, [&](std::size_t i) { return s.forces.density[i]; });
    s.model.rho0 = total / static_cast<double>(n);
    if (s.model.pressure) compute_forces(kernel, s.set, s.model, s.forces, &s.pairs);
    for (auto* v : {&s.vx, &s.vy, &s.vz, &s.ux, &s.uy, &s.uz}) v->assign(n, 0.0);
    return s;
}

// Step step.step of the method: false where the integration diverges. Particles brought to one
// position after the first step are the pairing instability (W' = 0 at r = 0 leaves a pair no
// force apart): RelaxDiverged, with the history so far.
bool take_step(const Kernel& kernel, RelaxState& s, const RelaxSettings& settings, double dt, double damping,
               RelaxStep& step, RelaxResult& result)
{
    try {
        return settings.method == RelaxMethod::pressure ? pressure_step(kernel, s, dt, damping, step)
                                                        : shift_step(kernel, s, settings, step);
    } catch (const CoincidentParticles& e) {
        if (step.step == 1) throw; // the set as given
        throw RelaxDiverged(
            fmt::format("{}: at step {} (t = {:.4g} d/c) particles {} and {} met at one position, where "
                        "no SPH sum is defined: the pairing instability merged them (the set as given "
                        "had them apart); expected a setting where the set is stable (sphkern "
                        "stability at this k) or fewer steps",
                        s.set.name, step.step, (step.step - 1) * result.dt, e.first, e.second),
            std::move(result.history));
    }
}

// Whether the RMS e0 of the last settle_steps + 1 steps spans less than settle_change of its largest.
bool settled(const std::vector<RelaxStep>& history, const RelaxSettings& settings)
{
    const auto window = static_cast<std::size_t>(settings.settle_steps) + 1;
    if (settings.settle_steps <= 0 || history.size() < window) return false;
    double low = INFINITY, high = 0;
    for (auto s = history.end() - static_cast<std::ptrdiff_t>(window); s != history.end(); ++s)
        low = std::min(low, s->rms_e0), high = std::max(high, s->rms_e0);
    return high - low < settings.settle_change * high;
}

} // namespace

RelaxResult relax_particles(const Kernel& kernel, ParticleSet set, double h, const RelaxSettings& settings,
                            const std::function<void(const RelaxState&, const RelaxStep&)>& observe)
{
    if (!set.box)
        fail_input(
            fmt::format("{}: relaxation needs a periodic box; expected a lattice block, poisson or a file with a box",
                        set.name));
    kernel.require_dimension(set.dimension, set.name);
    RelaxResult result;
    result.spacing = length_unit(set);
    result.h = h;
    if (!std::isfinite(h) || h <= 0) fail_input(fmt::format("{}: h = {:g} is not positive", set.name, h));
    PhaseTimes phases;
    result.state = start_state(kernel, std::move(set), h, settings, result.spacing);
    RelaxState& s = result.state;
    phases.lap("start");
    s.forces.phases = {};
    // c is one d per unit time: a time step of time_step h / c is time_step h / d units of d / c.
    const double dt = settings.time_step * h / result.spacing;
    result.dt = settings.method == RelaxMethod::pressure ? dt : 0;
    const double damping = settings.damping / h * result.spacing; // c / h in units of 1 / time
    RelaxStep start;
    record_errors(s, start);
    result.history.push_back(start);
    if (observe) observe(s, start);
    spdlog::debug("{}: relaxing {} particles, h = {:.6g}, method {}", s.set.name, s.set.size(), h,
                  relax_method_name(settings.method));
    Progress progress(s.set.name + ": relaxation", static_cast<std::size_t>(settings.steps));
    result.stop = "steps";
    phases.restart();
    for (int n = 1; n <= settings.steps; ++n) {
        throw_if_interrupted();
        RelaxStep step;
        step.step = n;
        if (!take_step(kernel, s, settings, dt, damping, step, result))
            fail_diverged(s, settings, step, result.dt, std::move(result.history));
        step.time = settings.method == RelaxMethod::pressure ? n * result.dt : 0;
        record_errors(s, step);
        result.history.push_back(step);
        if (observe) observe(s, step);
        progress.step(fmt::format("step {}: RMS move {:.3g} h, RMS e0 {:.3g}", n, step.rms_move, step.rms_e0));
        if (settings.tolerance > 0 && step.rms_move < settings.tolerance) {
            result.stop = "tolerance";
            break;
        }
        if (settled(result.history, settings)) {
            result.stop = "settled";
            break;
        }
    }
    // The steps' time less their passes' is the rest: kicks, moves and the errors.
    phases.lap("steps");
    double passes = 0;
    spdlog::debug("{}: {} pair lists built", s.set.name, s.pairs.builds);
    for (const auto& [name, seconds] : s.forces.phases.phases()) result.phases.add(name, seconds), passes += seconds;
    result.phases.add("start", phases.phases().front().second);
    result.phases.add("moves", std::max(0.0, phases.phases().back().second - passes));
    return result;
}

} // namespace sphkern
