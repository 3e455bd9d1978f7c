#include "stability/zone_grid.hpp"

#include "support/process/parallel_for.hpp"

#include <boost/math/tools/minima.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace sphkern {

namespace {

// The index of the grid point with centred integer coordinates m (fractions m / n), wrapped.
std::size_t index_of(const Eigen::Vector3i& m, int n, int D)
{
    std::size_t index = 0;
    for (int a = D - 1; a >= 0; --a) {
        const int c = ((m[a] + n / 2) % n + n) % n;
        index = index * static_cast<std::size_t>(n) + static_cast<std::size_t>(c);
    }
    return index;
}

Eigen::Vector3i centred(std::size_t index, int n, int D)
{
    Eigen::Vector3i m = Eigen::Vector3i::Zero();
    for (int a = 0; a < D; ++a, index /= static_cast<std::size_t>(n))
        m[a] = static_cast<int>(index % static_cast<std::size_t>(n)) - n / 2;
    return m;
}

} // namespace

ZoneGrid::ZoneGrid(const Dispersion& dispersion, const Eigen::Matrix3d& b, int n,
                   const std::vector<Eigen::Matrix3i>& symmetries, int threads)
    : n_(std::max(2, n + n % 2)), D_(dispersion.dimension())
{
    std::size_t total = 1;
    for (int a = 0; a < D_; ++a) total *= static_cast<std::size_t>(n_);
    // One representative per orbit: the first point met, whose images take its value (each
    // operation is a symmetry on its own, so this holds even if the set is not closed).
    std::vector<std::size_t> representative(total, total);
    std::vector<std::size_t> orbits;
    for (std::size_t i = 0; i < total; ++i) {
        if (representative[i] != total) continue;
        representative[i] = i;
        orbits.push_back(i);
        const Eigen::Vector3i m = centred(i, n_, D_);
        for (const auto& s : symmetries) {
            const std::size_t j = index_of(s * m, n_, D_);
            if (representative[j] == total) representative[j] = i;
        }
    }
    evaluated_ = orbits.size();
    const int branches = dispersion.branches();
    std::vector<std::vector<double>> values(orbits.size());
    ParallelFor pool;
    pool.run(orbits.size(), threads, [&](int, std::size_t begin, std::size_t end) {
        for (std::size_t o = begin; o < end && (o % 64 || pool.keep_going()); ++o)
            values[o] = dispersion.omega2(b * fraction(orbits[o]));
    });
    throw_if_interrupted();
    std::vector<std::size_t> slot(total);
    for (std::size_t o = 0; o < orbits.size(); ++o) slot[orbits[o]] = o;
    lowest_.resize(total);
    minimum_.assign(static_cast<std::size_t>(branches), INFINITY);
    minimum_at_.assign(static_cast<std::size_t>(branches), 0);
    for (std::size_t i = 0; i < total; ++i) {
        const auto& v = values[slot[representative[i]]];
        lowest_[i] = v[0];
        for (std::size_t br = 0; br < v.size(); ++br)
            if (v[br] < minimum_[br]) minimum_[br] = v[br], minimum_at_[br] = i;
    }
}

Eigen::Vector3d ZoneGrid::fraction(std::size_t index) const
{
    return centred(index, n_, D_).cast<double>() / n_;
}

std::size_t ZoneGrid::gamma_index() const { return index_of(Eigen::Vector3i::Zero(), n_, D_); }

std::pair<double, std::size_t> ZoneGrid::branch_minimum(int branch) const
{
    return {minimum_[static_cast<std::size_t>(branch)], minimum_at_[static_cast<std::size_t>(branch)]};
}

std::vector<std::size_t> ZoneGrid::valleys(int count) const
{
    // Neighbour offsets in index space, per axis: -stride, 0, +stride, wrapped at the ends.
    const std::size_t n = static_cast<std::size_t>(n_);
    std::array<std::size_t, 3> stride{1, n, n * n};
    std::vector<std::size_t> floors;
    const std::size_t gamma = gamma_index();
    std::array<std::size_t, 3> c{0, 0, 0};
    for (std::size_t i = 0; i < lowest_.size(); ++i) {
        for (int a = 0; a < D_; ++a) c[a] = i / stride[a] % n;
        if (i == gamma) continue;
        bool floor = true;
        for (int offset = 0; offset < (D_ == 3 ? 27 : D_ == 2 ? 9 : 3) && floor; ++offset) {
            std::size_t j = 0;
            for (int a = 0, o = offset; a < D_; ++a, o /= 3) j += (c[a] + n + static_cast<std::size_t>(o % 3) - 1) % n * stride[a];
            floor = lowest_[j] >= lowest_[i];
        }
        if (floor) floors.push_back(i);
    }
    std::sort(floors.begin(), floors.end(), [&](std::size_t a, std::size_t b) { return lowest_[a] < lowest_[b]; });
    std::vector<std::size_t> distinct;
    for (std::size_t i : floors) {
        if (static_cast<int>(distinct.size()) == count) break;
        if (!distinct.empty() && std::abs(lowest_[i] - lowest_[distinct.back()]) <= 1e-12 * std::abs(lowest_[i])) continue;
        distinct.push_back(i);
    }
    return distinct;
}

std::pair<Eigen::Vector3d, double> refine_branch(const Dispersion& dispersion, const Eigen::Matrix3d& b, int branch,
                                                 Eigen::Vector3d f, double value, double reach, int sweeps)
{
    const auto br = static_cast<std::size_t>(branch);
    for (int sweep = 0; sweep < sweeps; ++sweep)
        for (int axis = 0; axis < dispersion.dimension(); ++axis) {
            auto along = [&](double x) {
                Eigen::Vector3d g = f;
                g[axis] = x;
                return dispersion.omega2(b * g)[br];
            };
            std::uintmax_t iterations = 60;
            auto [x, fx] = boost::math::tools::brent_find_minima(along, f[axis] - reach, f[axis] + reach, 20, iterations);
            if (fx < value) value = fx, f[axis] = x;
        }
    return {f, value};
}

} // namespace sphkern
