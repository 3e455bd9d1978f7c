#include "particles/particle_measures.hpp"

#include "kernels/kernel_validity.hpp"
#include "particles/engine/neighbour_gather.hpp"
#include "particles/engine/pair_pass.hpp"
#include "particles/neighbour_sums.hpp"
#include "support/error.hpp"
#include "support/process/parallel_for.hpp"

#include <Eigen/Eigenvalues>
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <ctime>
#include <optional>
#include <stdexcept>
#include <thread>

namespace sphkern {

double frobenius_norm(const std::array<double, 6>& E, int dimension)
{
    double sum = E[0] * E[0] + E[1] * E[1] + 2 * E[3] * E[3];
    if (dimension == 3) sum += E[2] * E[2] + 2 * (E[4] * E[4] + E[5] * E[5]);
    return std::sqrt(sum);
}

namespace {

using Clock = std::chrono::steady_clock;

// Of a symmetric tensor's top-left D x D block: closed forms (Eigen's computeDirect in 3D).
double smallest_eigenvalue(const Eigen::Matrix3d& T, int dimension)
{
    if (dimension == 2) return 0.5 * (T(0, 0) + T(1, 1)) - std::hypot(0.5 * (T(0, 0) - T(1, 1)), T(0, 1));
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
    solver.computeDirect(T, Eigen::EigenvaluesOnly);
    return solver.eigenvalues()(0);
}

// A per-particle input in the grid's point order, or its one value when every particle has it.
struct PointInputs {
    std::vector<double> per_point; // empty when uniform
    double all = 0;
    // `find_uniform`: an array of one value is taken as that value (not in a slab, whose
    // uniform values are the whole set's, said by the view).
    static PointInputs of(const NeighbourGrid& grid, const PerParticleView& given, bool find_uniform)
    {
        if (given.is_uniform()) return {{}, given.uniform};
        if (!find_uniform) return {grid.gather(given.values), 0.0};
        const std::span<const double> per_particle = given.values;
        const double v = per_particle.front();
        const bool uniform = !first_index_where(per_particle.size(), grid.threads(),
                                                [&](std::size_t i) { return per_particle[i] != v; });
        return uniform ? PointInputs{{}, v} : PointInputs{grid.gather(per_particle), 0.0};
    }
    PointValues view() const { return {per_point.empty() ? nullptr : per_point.data(), all}; }
};
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

} // namespace

// The sums of one particle and where they go: shared by the measures' own pass and the
// collector of another pass's (MeasureCollector), hence not in the file's anonymous namespace.
namespace measures_detail {

// One particle's results in sweep order, before they go to the particle's own (file) place.
struct PointResult {
    MeasureRecord scalars;
    double eps_rho;
    std::array<double, 3> e1, m1;
    std::array<double, 6> E;
    std::uint32_t i;
};

// The results of a run of clusters, kept contiguous in sweep order and written to the file
// order of the particles once per block: on a disordered set that order is random in memory,
// and stores scattered among the sums stall them. A block is small (it stays in L2), so its
// memory does not grow with the set.
class ResultBlock {
public:
    static constexpr std::size_t flush_at = 1024;
    PointResult& next()
    {
        results_.emplace_back();
        return results_.back();
    }
    bool full() const { return results_.size() >= flush_at; }
    std::size_t pairs() const { return pairs_; }
    void flush(ParticleMeasures& out)
    {
        constexpr std::size_t ahead = 8;
        const bool vectors = !out.e1.empty(), masses = !out.eps_rho.empty();
        for (std::size_t k = 0; k < results_.size(); ++k) {
            if (k + ahead < results_.size()) prefetch(out, results_[k + ahead].i);
            const PointResult& r = results_[k];
            out.scalars[r.i] = r.scalars;
            pairs_ += static_cast<std::size_t>(r.scalars.neighbours);
            if (masses) out.eps_rho[r.i] = r.eps_rho;
            if (vectors) out.e1[r.i] = r.e1, out.m1[r.i] = r.m1, out.E[r.i] = r.E;
        }
        results_.clear();
    }

private:
    // The destinations of a result a few ahead: the stores then find their lines in cache.
    static void prefetch(ParticleMeasures& out, std::size_t i)
    {
        // A record may straddle two lines.
        const char* record = reinterpret_cast<const char*>(&out.scalars[i]);
        __builtin_prefetch(record, 1), __builtin_prefetch(record + sizeof(MeasureRecord) - 1, 1);
        if (!out.eps_rho.empty()) __builtin_prefetch(&out.eps_rho[i], 1);
        if (!out.e1.empty())
            __builtin_prefetch(&out.e1[i], 1), __builtin_prefetch(&out.m1[i], 1), __builtin_prefetch(&out.E[i], 1);
    }
    std::vector<PointResult> results_;
    std::size_t pairs_ = 0; // the neighbours of the particles flushed
};

// One particle's measures from its neighbours at its own h, whichever pass gathered them.
struct PointMeasure {
    const Kernel& kernel;
    const ParticleSet& set;
    const MeasureInputs& in;
    double uniform_volume; // V_j of every j where positive; else V_j in nb.a
    bool with_mass;        // m_j in nb.b (else m_j = rho0 V_j)

    // How a measure finds W and W': computed from dx, dy, dz (with the mean pair h, nb.r holding
    // h_i / h_ij of each neighbour), or given in nb.w and nb.dw at h.
    enum class KernelValues { computed, pair_mean, given };

    // One fused pass over particle i's n neighbours in nb (dx, dy, dz, and a and b as above;
    // padded with zeros): r, q and 1 / r, W and W' in one kernel call, and every sum, over
    // arrays that stay in L1.
    void measure(std::size_t i, double h, double v_i, double m_i, std::size_t n, Neighbours& nb, KernelValues values,
                 ResultBlock& out) const
    {
        const int dim = set.dimension;
        const double k = h / in.spacing;
        const std::size_t padded = padded_count(n);
        distances(nb, padded, 1 / h);
        if (values == KernelValues::pair_mean)
            for (std::size_t j = 0; j < n; ++j) nb.q[j] *= nb.r[j];
        if (values != KernelValues::given) kernel.w_dw_batch(nb.q.data(), nb.w.data(), nb.dw.data(), padded, dim, k);
        if (values == KernelValues::pair_mean) pair_kernel_in_units_of(nb, n);
        double t[neighbour_sum_count];
        neighbour_sums(nb, padded, uniform_volume, with_mass, set.dimension == 3, t);
        const double w0 = kernel.w(0, dim, k), s0_total = t[s0] + v_i * w0;
        const double m1[3] = {t[m1x], t[m1y], t[m1z]}, e1[3] = {t[e1x], t[e1y], t[e1z]};
        const double E[6] = {t[exx], t[eyy], t[ezz], t[exy], t[exz], t[eyz]};
        const std::optional<double> sm_total = with_mass ? std::optional<double>(t[sm] + m_i * w0) : std::nullopt;
        PointResult& r = out.next();
        r.i = static_cast<std::uint32_t>(i);
        store(n, h, s0_total, sm_total, m1, e1, E, r);
        if (!std::isfinite(r.scalars.e0) || !std::isfinite(r.scalars.eps_gradp) || !std::isfinite(r.eps_rho))
            fail_non_finite(r, nb, h);
    }

    // W(r, h_ij) and W'(r, h_ij) in the units of h_i that the sums and `store` use: times
    // (h_i / h_ij)^D and (h_i / h_ij)^(D+1).
    void pair_kernel_in_units_of(Neighbours& nb, std::size_t n) const
    {
        for (std::size_t j = 0; j < n; ++j) {
            const double s = nb.r[j], sd = set.dimension == 3 ? s * s * s : s * s;
            nb.w[j] *= sd, nb.dw[j] *= sd * s;
        }
    }

    // Names the cause of a result that is not finite: the reference density, or the kernel at
    // a neighbour's q, or else an h the sums overflow at.
    [[noreturn]] void fail_non_finite(const PointResult& r, const Neighbours& nb, double h) const
    {
        if (std::isfinite(r.scalars.e0) && std::isfinite(r.scalars.eps_gradp))
            fail_input(fmt::format("{}: eps_rho of {} overflows a double (its masses over rho0 = {:g}); expected "
                                   "a reference density rho0 nearer the set's mass density",
                                   set.name, set.particle(r.i), in.rho0));
        fail_non_finite_sum(kernel, set.dimension, h / in.spacing, fmt::format("{} of {}", set.particle(r.i), set.name),
                            fmt::format("h = {:.6g}", h), {nb.q.data(), nb.count});
    }

    // sm: the sum of m_j W_ij, none when m_j = rho0 V_j (then eps_rho = e0).
    void store(std::size_t n, double h, double s0, std::optional<double> sm, const double* m1, const double* e1,
               const double* E, PointResult& out) const
    {
        const int dim = set.dimension;
        const double hd = dim == 3 ? h * h * h : h * h, hd1 = hd * h; // std::pow costs more than the sums of a particle
        MeasureRecord& scalars = out.scalars;
        scalars.e0 = s0 / hd - 1;
        out.eps_rho = sm ? *sm / hd / in.rho0 - 1 : scalars.e0;
        for (int a = 0; a < 3; ++a) out.m1[static_cast<std::size_t>(a)] = m1[a] / hd / h;
        for (int a = 0; a < 3; ++a) out.e1[static_cast<std::size_t>(a)] = e1[a] / hd1 * h;
        std::array<double, 6> tensor;
        for (int a = 0; a < 6; ++a) tensor[static_cast<std::size_t>(a)] = E[a] / hd1 - (a < dim ? 1.0 : 0.0);
        if (dim == 2) tensor[2] = tensor[4] = tensor[5] = 0;
        out.E = tensor;
        scalars.E_norm = frobenius_norm(tensor, dim);
        scalars.e1_norm = std::hypot(out.e1[0], out.e1[1], out.e1[2]),
        scalars.m1_norm = std::hypot(out.m1[0], out.m1[1], out.m1[2]);
        const Eigen::Vector3d g = in.gravity.value_or(set.gravity);
        Eigen::Matrix3d T;
        T << tensor[0], tensor[3], tensor[4], tensor[3], tensor[1], tensor[5], tensor[4], tensor[5], tensor[2];
        scalars.eps_gradp = g.dot(T * g);
        scalars.lambda_min = smallest_eigenvalue(T, dim) + 1;
        const Eigen::Vector3d e1v(out.e1[0], out.e1[1], out.e1[2]);
        scalars.eps_gradp_sum = scalars.eps_gradp + 2 * in.depth * e1v.dot(g);
        scalars.neighbours = static_cast<int>(n);
    }
};

} // namespace measures_detail

namespace {

using namespace measures_detail;

struct Sweep {
    PointMeasure point;
    const NeighbourGrid& grid;
    // V, h and the support radius (with its edge) in point order: read in sweep order, not by
    // the particles' own (file) order, which on a disordered set is random in memory. Where
    // every particle has the same, nothing is gathered (8 bytes a point fewer for each), and a
    // uniform V is not gathered per neighbour either (one compress fewer per eight candidates,
    // on every lattice and Poisson set).
    PointInputs volume, h, reach;
    std::vector<double> mass; // in point order; empty: m_j = rho0 V_j
    // The mean pair h (h per point): each neighbour's point comes in nb.b (a double holds it
    // exactly), its mass is read from `mass` by it.
    bool pair_mean = false;

    void measure(std::size_t p, Neighbours& nb, ResultBlock& out) const
    {
        const double h = this->h.view()[p];
        const std::size_t n = pair_mean ? keep_pair_supports(h, nb) : nb.count;
        point.measure(grid.source(p), h, volume.view()[p], mass.empty() ? 0.0 : mass[p], n, nb,
                      pair_mean ? PointMeasure::KernelValues::pair_mean : PointMeasure::KernelValues::computed, out);
    }

    // The neighbours inside the support R h_ij of their pair, h_ij = (h_i + h_j) / 2, moved to
    // the front in their order, with m_j in nb.b and h_i / h_ij in nb.r; then the padding.
    std::size_t keep_pair_supports(double h_i, Neighbours& nb) const
    {
        const bool volumes = volume.view().per_point != nullptr;
        std::size_t kept = 0;
        for (std::size_t j = 0; j < nb.count; ++j) {
            const auto point = static_cast<std::size_t>(nb.b[j]);
            const double h_ij = 0.5 * (h_i + h.per_point[point]),
                         edge = search_reach(this->point.kernel.support() * h_ij);
            if (nb.dx[j] * nb.dx[j] + nb.dy[j] * nb.dy[j] + nb.dz[j] * nb.dz[j] > edge * edge) continue;
            nb.dx[kept] = nb.dx[j], nb.dy[kept] = nb.dy[j], nb.dz[kept] = nb.dz[j];
            if (volumes) nb.a[kept] = nb.a[j];
            nb.b[kept] = mass.empty() ? 0.0 : mass[point];
            nb.r[kept] = h_i / h_ij;
            ++kept;
        }
        for (std::size_t j = kept; j < padded_count(kept); ++j)
            nb.dx[j] = nb.dy[j] = nb.dz[j] = nb.a[j] = nb.b[j] = 0, nb.r[j] = 1;
        nb.count = kept;
        return kept;
    }
};

// The search reach of every particle's support radius R h, from h in point order (one for all
// for one h); with the mean pair h, of R (h + h_max) / 2, the widest of its pairs.
PointInputs reaches(const NeighbourGrid& grid, const PointInputs& h, double support, bool pair_mean, double h_max)
{
    PointInputs r = h;
    auto reach = [&](double h_i) { return search_reach(support * (pair_mean ? 0.5 * (h_i + h_max) : h_i)); };
    r.all = reach(r.all);
    ParallelFor pass;
    pass.run(r.per_point.size(), grid.threads(), [&](int, std::size_t begin, std::size_t end) {
        for (std::size_t p = begin; p < end; ++p) r.per_point[p] = reach(r.per_point[p]);
    });
    return r;
}

// 0, 1, 2, ... for every point of the grid: what the mean pair h gathers to find a neighbour's h and mass.
std::vector<double> point_numbers(const NeighbourGrid& grid)
{
    std::vector<double> numbers(grid.points());
    for (std::size_t p = 0; p < numbers.size(); ++p) numbers[p] = static_cast<double>(p);
    return numbers;
}

// `with_h`: the inputs carry every particle's h (a collector's particles bring their own).
void check_inputs(const ParticleSet& set, const MeasureInputs& in, bool with_h = true)
{
    const std::size_t n = set.size();
    if ((with_h && in.h.size() != n) || in.volume.size() != n || (!in.mass.empty() && in.mass.size() != n))
        fail_input(fmt::format("{}: smoothing lengths, volumes or masses missing for some particles", set.name));
    if (!std::isfinite(in.rho0) || in.rho0 <= 0)
        fail_input(fmt::format("the reference density {} is not positive", in.rho0));
    if (!std::isfinite(in.depth) || in.depth < 0)
        fail_input(fmt::format("the depth {} of eps_gradp_sum is not a non-negative number", in.depth));
    if (!std::isfinite(in.spacing) || in.spacing <= 0)
        fail_input(fmt::format("{}: the mean spacing is not positive", set.name));
}

} // namespace

ParticleMeasures measure_particles(const Kernel& kernel, const ParticleSet& set, const MeasureInputs& inputs)
{
    check_inputs(set, inputs);
    kernel.require_dimension(set.dimension, set.name);
    const double h_max = inputs.slab             ? inputs.slab->h_max
                         : inputs.h.is_uniform() ? inputs.h.uniform
                                                 : parallel_reduce(
                                                       set.size(), worker_threads(inputs.threads), 0.0,
                                                       [&](std::size_t i, double& m) { m = std::max(m, inputs.h[i]); },
                                                       [](double& m, double block) { m = std::max(m, block); });
    require_usable_kernel(kernel, set.dimension, h_max / inputs.spacing);
    PhaseTimes phases;
    ParticleMeasures out;
    out.threads = worker_threads(inputs.threads);
    const NeighbourGrid grid(set, kernel.support() * h_max, out.threads, inputs.slab ? &inputs.slab->window : nullptr);
    const bool find_uniform = !inputs.slab;
    PointInputs h_points = PointInputs::of(grid, inputs.h, find_uniform);
    // One h for every particle makes every pair's h that h.
    const bool pair_mean = inputs.pair == PairSmoothing::mean && !h_points.per_point.empty();
    PointInputs reach_points = reaches(grid, h_points, kernel.support(), pair_mean, h_max);
    PointInputs volume_points = PointInputs::of(grid, inputs.volume, find_uniform);
    const double uniform_volume = volume_points.per_point.empty() ? volume_points.all : 0.0;
    const Sweep sweep{{kernel, set, inputs, uniform_volume, !inputs.mass.empty()},
                      grid,
                      std::move(volume_points),
                      std::move(h_points),
                      std::move(reach_points),
                      inputs.mass.empty() ? std::vector<double>() : grid.gather(inputs.mass),
                      pair_mean};
    const std::vector<double> neighbour_points = pair_mean ? point_numbers(grid) : std::vector<double>();

    phases.lap("grid");
    // The measured particles only: the neighbours-only ones end the set and are not visited.
    const std::size_t n = set.measured();
    // Written in the particles' own order, random in memory on a disordered set.
    out.scalars.resize(n);
    if (!inputs.mass.empty()) out.eps_rho.resize(n);
    if (inputs.vectors) out.e1.resize(n), out.m1.resize(n), out.E.resize(n);
    spdlog::debug("{}: {} particles and {} ghosts on {} threads ({} of the particles neighbours only)", set.name,
                  set.size(), grid.points() - set.size(), out.threads, set.neighbours_only);
    auto t0 = Clock::now();
    const std::clock_t c0 = std::clock();                                    // the process's CPU time, every thread
    std::vector<ResultBlock> results(static_cast<std::size_t>(out.threads)); // one per thread
    const double* b = pair_mean ? neighbour_points.data() : sweep.mass.empty() ? nullptr : sweep.mass.data();
    const PairPassInputs pass{sweep.reach.view(), sweep.volume.view().per_point, b, false, set.name + ": the sums"};
    pair_pass(
        grid, set.name, pass, out.threads,
        [&](int thread, std::size_t p, Neighbours& nb) {
            ResultBlock& block = results[static_cast<std::size_t>(thread)];
            sweep.measure(p, nb, block);
            if (block.full()) block.flush(out);
        },
        [&](int thread) { results[static_cast<std::size_t>(thread)].flush(out); });
    out.seconds = seconds_since(t0);
    out.cpu_seconds = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
    for (const ResultBlock& block : results) out.pairs += block.pairs();
    phases.lap("sums");
    out.phases = phases;
    return out;
}

struct MeasureCollector::State {
    PointMeasure point; // holds the set and the inputs
    std::vector<ResultBlock> results;
    ParticleMeasures out;
};

MeasureCollector::MeasureCollector(const Kernel& kernel, const ParticleSet& set, const MeasureInputs& inputs,
                                   int threads)
{
    check_inputs(set, inputs, false);
    if (inputs.slab || inputs.pair == PairSmoothing::mean || set.neighbours_only > 0)
        throw std::logic_error("MeasureCollector: each particle's own h over one array of particles only");
    kernel.require_dimension(set.dimension, set.name);
    const double uniform_volume = inputs.volume.is_uniform() ? inputs.volume.uniform : 0.0;
    state_.reset(new State{{kernel, set, inputs, uniform_volume, !inputs.mass.empty()}, {}, {}});
    ParticleMeasures& out = state_->out;
    out.threads = worker_threads(threads);
    state_->results.resize(static_cast<std::size_t>(out.threads));
    out.scalars.resize(set.size());
    if (!inputs.mass.empty()) out.eps_rho.resize(set.size());
    if (inputs.vectors) out.e1.resize(set.size()), out.m1.resize(set.size()), out.E.resize(set.size());
}

MeasureCollector::~MeasureCollector() = default;

bool MeasureCollector::volumes_differ() const { return !(state_->point.uniform_volume > 0); }

std::span<const double> MeasureCollector::volumes() const { return state_->point.in.volume.values; }

bool MeasureCollector::with_mass() const { return state_->point.with_mass; }

double MeasureCollector::spacing() const { return state_->point.in.spacing; }

void MeasureCollector::measure(int thread, std::size_t i, double h, std::size_t n, Neighbours& nb, bool kernel_values)
{
    State& s = *state_;
    ResultBlock& block = s.results[static_cast<std::size_t>(thread)];
    using Values = PointMeasure::KernelValues;
    s.point.measure(i, h, s.point.in.volume[i], s.point.with_mass ? s.point.in.mass[i] : 0.0, n, nb,
                    kernel_values ? Values::given : Values::computed, block);
    if (block.full()) block.flush(s.out);
}

ParticleMeasures MeasureCollector::finish()
{
    for (ResultBlock& block : state_->results) {
        block.flush(state_->out);
        state_->out.pairs += block.pairs();
    }
    return std::move(state_->out);
}

} // namespace sphkern
