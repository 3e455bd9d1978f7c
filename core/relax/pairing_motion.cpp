#include "relax/pairing_motion.hpp"
#include "support/text/setting_names.hpp"

#include "particles/sources/lattice_particles.hpp"
#include "relax/glass_quality.hpp"
#include "relax/relaxation.hpp"
#include "stability/brillouin_zone.hpp"
#include "stability/dispersion.hpp"
#include "stability/mode_kind.hpp"
#include "stability/stability_budget.hpp"
#include "stability/stability_over_k.hpp"
#include "support/error.hpp"
#include "support/process/parallel_for.hpp"

#include <Eigen/LU>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace sphkern {

namespace {

// Cells along each axis: the smallest even number whose block is more than twice the support wide.
int block_cells(const Lattice& lattice, double reach)
{
    const Eigen::Matrix3d inverse = lattice.basis.inverse();
    int cells = 4;
    for (int a = 0; a < lattice.dimension; ++a) {
        const double width = 1 / inverse.row(a).norm(); // between the cell's faces along axis a
        cells = std::max(cells, 2 * static_cast<int>(std::ceil(reach * (1 + 1e-6) / width)));
    }
    return cells;
}

// x(t) / x(0) of a damped mode x'' + b x' + omega2 x = 0 that starts at rest: the linear
// history of one normal mode. Growth is capped at e^200 (the motion is nonlinear long before).
double mode_factor(double omega2, double b, double t)
{
    const double disc = b * b / 4 - omega2;
    if (disc > 0) {
        const double root = std::sqrt(disc), plus = -b / 2 + root, minus = -b / 2 - root;
        const double grow = std::min(plus * t, 200.0);
        return (-minus * std::exp(grow) + plus * std::exp(minus * t)) / (plus - minus);
    }
    if (disc == 0) return (1 + b * t / 2) * std::exp(-b * t / 2);
    const double w = std::sqrt(-disc);
    return std::exp(-b * t / 2) * (std::cos(w * t) + b / (2 * w) * std::sin(w * t));
}

// Over the modes a periodic block of `cells` cells per axis carries (kappa = sum m_a b_a / cells):
// the lowest omega^2, and the RMS of the modes' linear factors after `duration`. Noise that is
// independent per particle and axis puts the same mean square into every normal mode, so the
// RMS displacement grows by that factor while the motion stays linear.
struct BlockPrediction {
    double lowest = INFINITY;
    double rms_factor = 0;
};
BlockPrediction block_prediction(const Dispersion& dispersion, const ReciprocalLattice& reciprocal, int dim, int cells,
                                 double damping, double duration)
{
    BlockPrediction p;
    double sum = 1.0 * dispersion.branches(); // kappa = 0: a uniform shift, which stays
    std::size_t modes = static_cast<std::size_t>(dispersion.branches());
    const int n3 = dim == 3 ? cells : 1;
    for (int m1 = 0; m1 < cells; ++m1)
        for (int m2 = 0; m2 < cells; ++m2)
            for (int m3 = 0; m3 < n3; ++m3) {
                if (m1 == 0 && m2 == 0 && m3 == 0) continue;
                const Eigen::Vector3d kappa = reciprocal.vectors * Eigen::Vector3d(m1, m2, m3) / cells;
                for (double omega2 : dispersion.omega2(kappa)) {
                    p.lowest = std::min(p.lowest, omega2);
                    const double g = mode_factor(omega2, damping, duration);
                    sum += g * g, ++modes;
                }
            }
    p.rms_factor = std::sqrt(sum / static_cast<double>(modes));
    return p;
}

// x - site by the minimum image of the block's box, summed in blocks on `threads` threads.
double displacement_rms(const ParticleSet& set, const ParticleSet& sites, int threads)
{
    Eigen::Matrix3d cell = set.box->edges;
    if (set.dimension == 2) cell.col(2) = Eigen::Vector3d::UnitZ();
    const Eigen::Matrix3d inverse = cell.inverse();
    const double sum = parallel_sum(set.size(), worker_threads(threads), [&](std::size_t i) {
        Eigen::Vector3d f = inverse * (set.position(i) - sites.position(i));
        for (int a = 0; a < set.dimension; ++a) f[a] -= std::round(f[a]);
        return (cell * f).squaredNorm();
    });
    return std::sqrt(sum / static_cast<double>(set.size()));
}

// The slope of ln(rms) against time over the samples where it grew from 3x its start to 0.05 d.
double fitted_rate(const std::vector<std::pair<double, double>>& series, double start)
{
    double st = 0, sy = 0, stt = 0, sty = 0, n = 0;
    for (const auto& [t, rms] : series) {
        if (rms < 3 * start || rms > 0.05) continue;
        const double y = std::log(rms);
        st += t, sy += y, stt += t * t, sty += t * y, n += 1;
    }
    if (n < 3) return 0;
    const double denominator = n * stt - st * st;
    return denominator > 0 ? (n * sty - st * sy) / denominator : 0;
}

std::string outcome_of(const PairingPoint& p)
{
    if (p.paired_end >= 0.05 && p.paired_end > p.paired_start) return "paired";
    if (p.rms_max > 10 * p.rms_start) return "grew";
    if (p.rms_end < 0.5 * p.rms_start) return "returned";
    return "held";
}

// What the linear answer predicts for the run: growth into the nonlinear regime (the linear
// RMS displacement passes 0.1 d: pairs for a longitudinal mode), growth by 10x, a return to
// the sites (the RMS displacement at most halves), or too little change to tell.
std::string expected_of(const PairingPoint& p)
{
    if (p.rms_start * p.predicted_factor >= 0.1) return p.kind == "longitudinal" ? "paired" : "grew";
    if (p.predicted_factor >= 10) return "grew";
    if (p.predicted_factor <= 0.5) return "returned";
    return "either";
}

bool agrees(const std::string& expected, const std::string& outcome)
{
    if (expected == "either") return true;
    if (expected == "grew") return outcome == "grew" || outcome == "paired";
    return expected == outcome;
}

// Pair evaluations of one sample: two force passes a step over the block's particles and
// their neighbours, and the block's wave vectors in the linear prediction.
double pairing_pair_terms(const Kernel& kernel, const Lattice& lattice, double k, const PairingRequest& r)
{
    const double cells = std::pow(block_cells(lattice, kernel.support() * k), lattice.dimension);
    const double neighbours = dispersion_neighbours(kernel, lattice, k); // of all the sites of a cell
    const double steps = std::max(1.0, std::ceil(r.duration / (r.time_step * k)));
    return (2 * steps + 1) * cells * neighbours;
}

// Over this, a request is refused before any motion (about a quarter of a minute on two cores).
constexpr double max_pairing_pair_terms = 1e10;

PairingPoint run_one(const Kernel& kernel, const Lattice& lattice, double k, const PairingRequest& r)
{
    PairingPoint p;
    p.k = k;
    const Dispersion dispersion(kernel, lattice, k, r.gamma);
    const ReciprocalLattice reciprocal = reciprocal_lattice(lattice);
    const StabilitySample sample = stability_sample(dispersion, reciprocal, 0, std::max(1, r.threads), r.horizon);
    p.verdict = sample.verdict;
    p.cells = block_cells(lattice, kernel.support() * k);
    // The motion can only grow the wave vectors the block carries: the prediction uses those.
    const double b = r.damping / k; // c / h in units of c / d
    const BlockPrediction predicted =
        block_prediction(dispersion, reciprocal, lattice.dimension, p.cells, b, r.duration);
    p.omega2 = std::min(0.0, predicted.lowest);
    p.predicted_factor = predicted.rms_factor;
    if (p.omega2 < -unstable_threshold) {
        p.growth_time = 1 / std::sqrt(-p.omega2);
        p.kind = mode_kind_name(sample.mode.kind);
        p.predicted_rate = -b / 2 + std::sqrt(b * b / 4 - p.omega2);
    } else {
        p.growth_time = std::numeric_limits<double>::infinity();
    }
    LatticeBlockSpec spec;
    spec.cells = {p.cells, p.cells, lattice.dimension == 3 ? p.cells : 1};
    const ParticleSet sites = lattice_particles(lattice, spec, worker_threads(r.threads));
    spec.sigma = r.noise, spec.seed = r.seed;
    ParticleSet start = lattice_particles(lattice, spec, worker_threads(r.threads));
    p.particles = start.size();
    RelaxSettings settings;
    settings.method = RelaxMethod::pressure;
    settings.time_step = r.time_step, settings.damping = r.damping, settings.gamma = r.gamma,
    settings.threads = r.threads;
    settings.steps = std::max(1, static_cast<int>(std::ceil(r.duration / (r.time_step * k))));
    std::vector<std::pair<double, double>> series;
    p.rms_start = displacement_rms(start, sites, r.threads);
    p.paired_start = paired_fraction(start, r.threads);
    const RelaxResult run =
        relax_particles(kernel, std::move(start), k, settings, [&](const RelaxState& s, const RelaxStep& step) {
            series.emplace_back(step.time, displacement_rms(s.set, sites, r.threads));
        });
    p.rms_end = series.back().second;
    for (const auto& point : series) p.rms_max = std::max(p.rms_max, point.second);
    p.paired_end = paired_fraction(run.state.set, r.threads);
    p.measured_rate = fitted_rate(series, p.rms_start);
    p.outcome = outcome_of(p);
    p.expected = expected_of(p);
    p.agrees = agrees(p.expected, p.outcome);
    return p;
}

} // namespace

std::vector<PairingPoint> pairing_motion(const Kernel& kernel, const Lattice& lattice, const PairingRequest& request)
{
    auto k_of = [&](int i) {
        return request.samples == 1 ? request.k_min
                                    : request.k_min + (request.k_max - request.k_min) * i / (request.samples - 1);
    };
    double terms = 0;
    for (int i = 0; i < request.samples; ++i) terms += pairing_pair_terms(kernel, lattice, k_of(i), request);
    if (terms > max_pairing_pair_terms)
        fail_input(
            fmt::format("pairing: the motion asks for {:.3g} pair evaluations over its {} sample(s) of k, over the "
                        "limit of {:.3g}; expected a smaller k, a shorter {} or fewer {}",
                        terms, request.samples, max_pairing_pair_terms, setting_named("duration"),
                        setting_named("samples")));
    std::vector<PairingPoint> points;
    for (int i = 0; i < request.samples; ++i) points.push_back(run_one(kernel, lattice, k_of(i), request));
    return points;
}

} // namespace sphkern
