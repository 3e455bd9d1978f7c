#include "stability/stability_scan.hpp"

#include "stability/zone_minimum.hpp"
#include "support/error.hpp"

#include <Eigen/Eigenvalues>
#include <fmt/format.h>

#include <boost/math/tools/minima.hpp>

#include <algorithm>
#include <cmath>
#include <complex>
#include <tuple>

namespace sphkern {

namespace {

// omega^2 / kappa^2 and the longitudinal fraction of the D acoustic modes at kappa n (those
// whose sites move most nearly in phase; all of them for one site), ascending. Unstable
// optical modes may lie below them.
std::vector<std::pair<double, double>> acoustic_ratios(const Dispersion& dispersion, const Eigen::Vector3d& n,
                                                       double kappa)
{
    const int D = dispersion.dimension();
    const auto modes = dispersion.modes(kappa * n);
    std::vector<std::pair<double, int>> in_phase;
    for (int b = 0; b < dispersion.branches(); ++b) {
        double together = 0;
        for (int a = 0; a < D; ++a) {
            std::complex<double> sum = 0;
            for (int site = 0; site < dispersion.sites(); ++site) sum += modes.modes[b][D * site + a];
            together += std::norm(sum);
        }
        in_phase.emplace_back(-together, b);
    }
    std::sort(in_phase.begin(), in_phase.end());
    std::vector<std::pair<double, double>> r;
    for (int i = 0; i < D; ++i) {
        const int b = in_phase[static_cast<std::size_t>(i)].second;
        r.emplace_back(modes.omega2[b] / (kappa * kappa), modes.longitudinal[b]);
    }
    std::sort(r.begin(), r.end());
    return r;
}

// The lowest omega^2 / kappa^2 of the acoustic branches at kappa n from the eigenvalues alone:
// at long waves they are the D nearest zero (O(kappa^2)), the optical ones stay O(1) away.
double lowest_acoustic(const Dispersion& dispersion, const Eigen::Vector3d& n, double kappa)
{
    auto w = dispersion.omega2(kappa * n);
    std::sort(w.begin(), w.end(), [](double a, double b) { return std::abs(a) < std::abs(b); });
    return *std::min_element(w.begin(), w.begin() + dispersion.dimension()) / (kappa * kappa);
}

} // namespace

int default_grid(int dimension) { return zone_start_grid(dimension); }

std::string verdict_name(Verdict verdict)
{
    return verdict == Verdict::stable ? "stable" : verdict == Verdict::weak ? "weak" : "unstable";
}

void check_horizon(double horizon, const std::string& what)
{
    if (!std::isfinite(horizon) || horizon <= 0 || horizon > 1e12)
        throw Error(ExitCode::usage,
                    fmt::format("{} {} is not allowed, expected a growth time in (0, 1e12] (in d/c)", what, horizon));
}

double StabilityScan::growth_time() const
{
    const double w = lowest().omega2;
    return w < -unstable_threshold ? 1 / std::sqrt(-w) : INFINITY;
}

Verdict StabilityScan::verdict(double horizon) const
{
    if (stable) return Verdict::stable;
    return growth_time() < horizon ? Verdict::unstable : Verdict::weak;
}

StabilityScan scan_brillouin_zone(const Dispersion& dispersion, const ReciprocalLattice& reciprocal, int start_grid,
                                  int threads, bool refine_all)
{
    auto zone = lowest_branch_minimum(dispersion, reciprocal, start_grid, threads);
    const ZoneGrid& grid = *zone.last;
    StabilityScan scan;
    scan.grid = grid.per_axis();
    scan.grid_points = static_cast<int>(grid.size());
    scan.levels = zone.levels;
    scan.converged = zone.converged;
    scan.change = zone.change;
    scan.floor = zone.floor;
    const Eigen::Matrix3d& b = reciprocal.vectors;
    for (int br = 0; br < dispersion.branches(); ++br) {
        BranchMinimum m;
        m.branch = br;
        Eigen::Vector3d f = zone.fraction;
        double value = zone.omega2;
        if (br > 0) {
            const auto [v, at] = grid.branch_minimum(br);
            std::tie(f, value) =
                refine_branch(dispersion, b, br, grid.fraction(at), v, 1.0 / grid.per_axis(), refine_all ? 6 : 0);
        }
        m.kappa = fold_to_first_zone(reciprocal, b * f);
        const auto modes = dispersion.modes(m.kappa);
        m.omega2 = br == 0 ? value : modes.omega2[static_cast<std::size_t>(br)];
        m.longitudinal = modes.longitudinal[static_cast<std::size_t>(br)];
        scan.minima.push_back(m);
        if (m.omega2 < -unstable_threshold) scan.stable = false;
    }
    std::stable_sort(scan.minima.begin(), scan.minima.end(),
                     [](const BranchMinimum& a, const BranchMinimum& c) { return a.omega2 < c.omega2; });
    scan.mode = mode_character(dispersion, reciprocal, scan.lowest().kappa, scan.lowest().branch);
    scan.long_wave = long_wave_minimum(dispersion);
    if (scan.long_wave.omega2_over_kappa2 < -unstable_threshold) scan.stable = false;
    return scan;
}

LongWaveMinimum long_wave_minimum(const Dispersion& dispersion)
{
    const int D = dispersion.dimension();
    // Directions by two angles (the polar one fixed in 2D). One site: the exact limit matrix;
    // several: omega^2 / kappa^2 of the lowest branch at kappa = 1e-3 and 2e-3,
    // Richardson-extrapolated to kappa -> 0.
    auto direction = [&](double theta, double phi) {
        return D == 3
                   ? Eigen::Vector3d(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta))
                   : Eigen::Vector3d(std::cos(phi), std::sin(phi), 0);
    };
    auto ratio = [&](double theta, double phi) {
        const Eigen::Vector3d n = direction(theta, phi);
        if (dispersion.sites() == 1) {
            const Eigen::MatrixXd m = dispersion.long_wave_matrix(n).topLeftCorner(D, D);
            return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(m, Eigen::EigenvaluesOnly).eigenvalues()[0];
        }
        const double small = lowest_acoustic(dispersion, n, 1e-3), larger = lowest_acoustic(dispersion, n, 2e-3);
        return (4 * small - larger) / 3;
    };
    // omega^2(kappa) = omega^2(-kappa): half the directions suffice.
    // Several sites cost an eigensolver per direction: a coarser start, the same refinement.
    const int fine = dispersion.sites() == 1 ? 2 : 1;
    const int polar = D == 3 ? 6 * fine : 1, azimuthal = D == 3 ? 12 * fine : 45 * fine;
    const double dtheta = M_PI / 2 / polar, dphi = M_PI / azimuthal;
    double theta = D == 3 ? 0 : M_PI / 2, phi = 0, best = INFINITY;
    for (int i = 0; i <= (D == 3 ? polar : 0); ++i)
        for (int j = 0; j < (D == 3 ? 2 : 1) * azimuthal; ++j) {
            const double t = D == 3 ? i * dtheta : M_PI / 2, p = j * dphi;
            const double v = ratio(t, p);
            if (v < best) best = v, theta = t, phi = p;
        }
    for (int sweep = 0; sweep < 3; ++sweep) {
        std::uintmax_t iterations = 50;
        auto [p, fp] = boost::math::tools::brent_find_minima([&](double x) { return ratio(theta, x); }, phi - dphi,
                                                             phi + dphi, 30, iterations);
        if (fp < best) best = fp, phi = p;
        if (D < 3) break;
        iterations = 50;
        auto [t, ft] = boost::math::tools::brent_find_minima([&](double x) { return ratio(x, phi); }, theta - dtheta,
                                                             theta + dtheta, 30, iterations);
        if (ft < best) best = ft, theta = t;
    }
    return {best, direction(theta, phi)};
}

SoundSpeed long_wave_sound_speed(const Dispersion& dispersion, const Eigen::Vector3d& direction)
{
    const int D = dispersion.dimension();
    SoundSpeed s;
    s.direction = direction.normalized();
    const auto small = acoustic_ratios(dispersion, s.direction, 1e-3),
               larger = acoustic_ratios(dispersion, s.direction, 2e-3);
    double most = -1;
    for (int b = 0; b < D; ++b) {
        // omega^2 / kappa^2 = c^2 + O(kappa^2): Richardson.
        const double c2 = (4 * small[b].first - larger[b].first) / 3;
        const double speed = std::copysign(std::sqrt(std::abs(c2)), c2); // negative: imaginary, unstable
        s.speeds.push_back(speed);
        if (small[b].second > most) most = small[b].second, s.longitudinal = speed;
    }
    std::sort(s.speeds.begin(), s.speeds.end());
    return s;
}

} // namespace sphkern
