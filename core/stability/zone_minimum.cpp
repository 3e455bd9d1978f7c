#include "stability/zone_minimum.hpp"

#include "stability/zone_polish.hpp"
#include "stability/zone_symmetry.hpp"
#include "support/process/interruption.hpp"

#include <Eigen/LU>
#include <boost/math/tools/minima.hpp>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>

namespace sphkern {

namespace {

struct Found {
    double value = INFINITY;
    Eigen::Vector3d fraction = Eigen::Vector3d::Zero();
    double floor = INFINITY;
    void offer(const std::pair<Eigen::Vector3d, double>& p, bool away_from_gamma)
    {
        if (p.second < value) value = p.second, fraction = p.first;
        if (away_from_gamma) floor = std::min(floor, p.second);
    }
};

// Minima of the lowest branch along each segment of the high-symmetry path (Γ-X, X-W, ...):
// `samples` points a segment, each interior local minimum refined along the segment and then
// coordinate-wise. A valley on a symmetry line is where instabilities usually start.
void line_minima(const Dispersion& dispersion, const ReciprocalLattice& reciprocal, int samples, double reach,
                 Found& found)
{
    const Eigen::Matrix3d& b = reciprocal.vectors;
    Eigen::Matrix3d full = b;
    for (int a = reciprocal.dimension; a < 3; ++a) full.col(a) = Eigen::Vector3d::Unit(a);
    const Eigen::Matrix3d to_fractions = full.inverse();
    const auto path = high_symmetry_path(reciprocal);
    for (std::size_t s = 0; s + 1 < path.size(); ++s) {
        const Eigen::Vector3d from = path[s].kappa, to = path[s + 1].kappa;
        if ((to - from).norm() < 1e-12) continue;
        auto at = [&](double t) { return dispersion.omega2(from + t * (to - from)).front(); };
        std::vector<double> v(static_cast<std::size_t>(samples + 1));
        for (int i = 0; i <= samples; ++i) v[static_cast<std::size_t>(i)] = at(static_cast<double>(i) / samples);
        for (int i = 1; i < samples; ++i) {
            const auto u = static_cast<std::size_t>(i);
            // A valley: no higher than either neighbour and lower than one (not a flat stretch).
            if (v[u] > v[u - 1] || v[u] > v[u + 1] || (v[u] == v[u - 1] && v[u] == v[u + 1])) continue;
            std::uintmax_t iterations = 60;
            const double step = 1.0 / samples;
            auto [t, value] = boost::math::tools::brent_find_minima(at, (i - 1) * step, (i + 1) * step, 30, iterations);
            const Eigen::Vector3d f = to_fractions * (from + t * (to - from));
            found.offer(refine_branch(dispersion, b, 0, f, value, reach, 2), true);
        }
    }
}

// Whether fractions f lie within `radius` (on every axis, periodically) of a symmetric
// image of a point refined before: a refinement from there has already searched that spot.
bool already_searched(const Eigen::Vector3d& f, const std::vector<Eigen::Vector3d>& searched,
                      const std::vector<Eigen::Matrix3i>& symmetries, double radius)
{
    for (const auto& p : searched)
        for (const auto& s : symmetries) {
            Eigen::Vector3d d = f - s.cast<double>() * p;
            for (int a = 0; a < 3; ++a) d[a] -= std::round(d[a]);
            if (d.cwiseAbs().maxCoeff() < radius) return true;
        }
    return false;
}

// One grid: its minimum and its valleys, refined unless an earlier grid searched there.
void grid_minima(const Dispersion& dispersion, const Eigen::Matrix3d& b, const ZoneGrid& grid,
                 const std::vector<Eigen::Matrix3i>& symmetries, std::vector<Eigen::Vector3d>& searched, Found& found)
{
    const double reach = 1.0 / grid.per_axis();
    auto refine_from = [&](std::size_t i, double value, int sweeps) {
        const Eigen::Vector3d f = grid.fraction(i);
        if (already_searched(f, searched, symmetries, 1.5 * reach)) return;
        const auto refined = refine_branch(dispersion, b, 0, f, value, reach, sweeps);
        searched.push_back(f);
        searched.push_back(refined.first);
        found.offer(refined, i != grid.gamma_index());
    };
    const auto [value, at] = grid.branch_minimum(0);
    refine_from(at, value, 4);
    for (std::size_t i : grid.valleys(zone_valleys)) refine_from(i, grid.lowest(i), 3);
    // The grid's own minimum counts even where it was not refined again.
    found.offer({grid.fraction(at), value}, at != grid.gamma_index());
}

// A tenth of the tolerance between grids: what one more round of polishing may still gain.
double polish_tolerance(double value)
{
    return 0.1 * (zone_tolerance_absolute + zone_tolerance_relative * std::abs(value));
}

} // namespace

int zone_start_grid(int dimension) { return dimension == 3 ? 8 : dimension == 2 ? 32 : 128; }

ZoneMinimum lowest_branch_minimum(const Dispersion& dispersion, const ReciprocalLattice& reciprocal, int start_grid,
                                  int threads)
{
    const int D = dispersion.dimension();
    const int start = start_grid > 0 ? start_grid : zone_start_grid(D);
    const auto symmetries = zone_symmetries(dispersion, reciprocal);
    ZoneMinimum result;
    Found lines;
    spdlog::debug("zone scan: minima along the high-symmetry path");
    line_minima(dispersion, reciprocal, 2 * start, 0.5 / start, lines);
    spdlog::debug("zone scan: the high-symmetry path searched");
    // Grids up to four times the default start (a larger start is used alone, unverified).
    const int largest = std::max(start, 4 * zone_start_grid(D));
    double previous = INFINITY;
    Found level = lines; // every minimum found so far: a finer grid can only lower it
    std::vector<Eigen::Vector3d> searched;
    for (int n = start; n <= largest; n *= 2) {
        throw_if_interrupted();
        result.last.emplace(dispersion, reciprocal.vectors, n, symmetries, threads);
        grid_minima(dispersion, reciprocal.vectors, *result.last, symmetries, searched, level);
        result.omega2 = level.value;
        result.fraction = level.fraction;
        result.floor = level.floor;
        result.grid = result.last->per_axis();
        ++result.levels;
        result.change = std::abs(level.value - previous);
        if (std::isfinite(previous) &&
            result.change <= zone_tolerance_absolute + zone_tolerance_relative * std::abs(level.value)) {
            result.converged = true;
            break;
        }
        previous = level.value;
    }
    if (result.levels == 1) result.change = 0; // a single grid: nothing to compare it with
    // Where a mode grows, its growth time is reported: follow the valley to its floor.
    if (result.omega2 < 0)
        std::tie(result.fraction, result.omega2) =
            polish_minimum(dispersion, reciprocal.vectors, result.fraction, result.omega2, 1.0 / result.grid,
                           polish_tolerance, 40);
    return result;
}

} // namespace sphkern
