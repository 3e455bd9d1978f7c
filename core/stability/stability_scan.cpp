#include "stability/stability_scan.hpp"

#include "support/parallel_for.hpp"

#include <boost/math/tools/minima.hpp>

#include <algorithm>
#include <cmath>
#include <complex>
#include <mutex>

namespace sphkern {

namespace {

// Distinct valleys refined besides the grid minimum.
constexpr int valley_candidates = 3;

// The grid's local minima (periodic neighbours, ties allowed) other than Γ, lowest first,
// one per value: symmetric copies of a valley are refined once.
std::vector<std::size_t> valley_floors(const std::vector<double>& value, int n, int D, int count)
{
    std::vector<std::size_t> floors;
    const std::size_t total = value.size();
    auto coordinate = [&](std::size_t index, int axis) {
        for (int a = 0; a < axis; ++a) index /= static_cast<std::size_t>(n);
        return static_cast<int>(index % static_cast<std::size_t>(n));
    };
    const std::size_t gamma = [&] { // fraction 0 on every axis: grid coordinate n / 2
        std::size_t index = 0;
        for (int a = D - 1; a >= 0; --a) index = index * static_cast<std::size_t>(n) + static_cast<std::size_t>(n / 2);
        return index;
    }();
    for (std::size_t i = 0; i < total; ++i) {
        if (i == gamma) continue;
        bool floor = true;
        for (int offset = 0; offset < (D == 3 ? 27 : D == 2 ? 9 : 3) && floor; ++offset) {
            std::size_t j = 0, stride = 1;
            int o = offset;
            for (int a = 0; a < D; ++a) {
                const int c = (coordinate(i, a) + (o % 3) - 1 + n) % n;
                o /= 3;
                j += static_cast<std::size_t>(c) * stride;
                stride *= static_cast<std::size_t>(n);
            }
            floor = value[j] >= value[i];
        }
        if (floor) floors.push_back(i);
    }
    std::sort(floors.begin(), floors.end(), [&](std::size_t a, std::size_t c) { return value[a] < value[c]; });
    std::vector<std::size_t> distinct;
    for (std::size_t i : floors) {
        if (static_cast<int>(distinct.size()) == count) break;
        if (!distinct.empty() && std::abs(value[i] - value[distinct.back()]) <= 1e-9 * std::abs(value[i])) continue;
        distinct.push_back(i);
    }
    return distinct;
}

} // namespace

int default_grid(int dimension) { return dimension == 3 ? 24 : dimension == 2 ? 96 : 512; }

StabilityScan scan_brillouin_zone(const Dispersion& dispersion, const ReciprocalLattice& reciprocal, int per_axis,
                                  int threads, bool refine_all)
{
    const int D = dispersion.dimension(), branches = dispersion.branches();
    const int n = std::max(2, per_axis + per_axis % 2);
    std::size_t total = 1;
    for (int i = 0; i < D; ++i) total *= static_cast<std::size_t>(n);
    const Eigen::Matrix3d& b = reciprocal.vectors;
    auto fraction_of = [&](std::size_t index) {
        Eigen::Vector3d f = Eigen::Vector3d::Zero();
        for (int i = 0; i < D; ++i) {
            f[i] = -0.5 + static_cast<double>(index % n) / n;
            index /= n;
        }
        return f;
    };
    // The lowest grid value of each branch, per thread, then merged; the lowest branch on
    // every grid point, for its local minima.
    struct Best {
        std::vector<double> value;
        std::vector<Eigen::Vector3d> at;
    };
    std::vector<Best> best(static_cast<std::size_t>(std::max(1, threads)),
                           Best{std::vector<double>(branches, INFINITY), std::vector<Eigen::Vector3d>(branches)});
    std::vector<double> lowest(total);
    ParallelFor pool;
    pool.run(total, threads, [&](int t, std::size_t begin, std::size_t end) {
        auto& mine = best[static_cast<std::size_t>(t)];
        for (std::size_t i = begin; i < end && (i % 256 || pool.keep_going()); ++i) {
            const Eigen::Vector3d f = fraction_of(i);
            const auto w = dispersion.omega2(b * f);
            lowest[i] = w[0];
            for (int br = 0; br < branches; ++br)
                if (w[br] < mine.value[br]) mine.value[br] = w[br], mine.at[br] = f;
        }
    });
    // Coordinate-wise Brent from a grid point, within one grid step on each axis.
    auto refine = [&](int br, Eigen::Vector3d f, double value, int sweeps) {
        for (int sweep = 0; sweep < sweeps; ++sweep)
            for (int axis = 0; axis < D; ++axis) {
                auto along = [&](double x) {
                    Eigen::Vector3d g = f;
                    g[axis] = x;
                    return dispersion.omega2(b * g)[br];
                };
                std::uintmax_t iterations = 60;
                auto [x, fx] = boost::math::tools::brent_find_minima(along, f[axis] - 1.0 / n, f[axis] + 1.0 / n, 20,
                                                                    iterations);
                if (fx < value) value = fx, f[axis] = x;
            }
        return std::pair{f, value};
    };
    StabilityScan scan;
    scan.grid_points = static_cast<int>(total);
    for (int br = 0; br < branches; ++br) {
        std::size_t winner = 0;
        for (std::size_t t = 1; t < best.size(); ++t)
            if (best[t].value[br] < best[winner].value[br]) winner = t;
        auto [f, value] = refine(br, best[winner].at[br], best[winner].value[br], refine_all || br == 0 ? 6 : 0);
        // The lowest branch: also its lowest grid valleys away from Γ, where an instability
        // starts as a valley floor crosses zero (the grid minimum may still be Γ then).
        if (br == 0)
            for (std::size_t i : valley_floors(lowest, n, D, valley_candidates)) {
                auto [g, v] = refine(0, fraction_of(i), lowest[i], 3);
                if (v < value) f = g, value = v;
            }
        BranchMinimum m;
        m.branch = br;
        m.kappa = fold_to_first_zone(reciprocal, b * f);
        const auto modes = dispersion.modes(m.kappa);
        m.omega2 = modes.omega2[br];
        m.longitudinal = modes.longitudinal[br];
        scan.minima.push_back(m);
        if (m.omega2 < -unstable_threshold) scan.stable = false;
    }
    std::stable_sort(scan.minima.begin(), scan.minima.end(),
                     [](const BranchMinimum& a, const BranchMinimum& c) { return a.omega2 < c.omega2; });
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
        return D == 3 ? Eigen::Vector3d(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta))
                      : Eigen::Vector3d(std::cos(phi), std::sin(phi), 0);
    };
    auto ratio = [&](double theta, double phi) {
        const Eigen::Vector3d n = direction(theta, phi);
        if (dispersion.sites() == 1) {
            const Eigen::MatrixXd m = dispersion.long_wave_matrix(n).topLeftCorner(D, D);
            return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(m, Eigen::EigenvaluesOnly).eigenvalues()[0];
        }
        const double small = dispersion.omega2(1e-3 * n).front() / 1e-6,
                     larger = dispersion.omega2(2e-3 * n).front() / 4e-6;
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
    // The acoustic modes are the D whose sites move in phase (all of them for one site);
    // unstable optical modes may lie below them.
    auto ratio = [&](double kappa) {
        const auto modes = dispersion.modes(kappa * s.direction);
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
        std::vector<std::pair<double, double>> r; // (omega^2 / kappa^2, longitudinal) of the acoustic modes
        for (int i = 0; i < D; ++i) {
            const int b = in_phase[static_cast<std::size_t>(i)].second;
            r.emplace_back(modes.omega2[b] / (kappa * kappa), modes.longitudinal[b]);
        }
        std::sort(r.begin(), r.end());
        return r;
    };
    const auto small = ratio(1e-3), larger = ratio(2e-3);
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
