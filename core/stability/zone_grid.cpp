#include "stability/zone_grid.hpp"

#include "support/process/parallel_for.hpp"

#include <boost/math/tools/minima.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <mutex>

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

struct GridOrbits {
    std::vector<std::size_t> orbits;   // the first point of each orbit, ascending
    std::vector<std::size_t> orbit_of; // per point: its orbit's place in `orbits`
};

// One representative per orbit: the first point met, whose images take its value (each
// operation is a symmetry on its own, so this holds even if the set is not closed).
GridOrbits find_orbits(int n, int D, const std::vector<Eigen::Matrix3i>& symmetries)
{
    std::size_t total = 1;
    for (int a = 0; a < D; ++a) total *= static_cast<std::size_t>(n);
    GridOrbits g;
    g.orbit_of.assign(total, total);
    for (std::size_t i = 0; i < total; ++i) {
        if (g.orbit_of[i] != total) continue;
        g.orbit_of[i] = g.orbits.size();
        const Eigen::Vector3i m = centred(i, n, D);
        for (const auto& s : symmetries) {
            const std::size_t j = index_of(s * m, n, D);
            if (g.orbit_of[j] == total) g.orbit_of[j] = g.orbits.size();
        }
        g.orbits.push_back(i);
    }
    return g;
}

// The orbits depend only on the grid and the symmetries, which every k of a scan shares:
// the last few are kept.
std::shared_ptr<const GridOrbits> grid_orbits(int n, int D, const std::vector<Eigen::Matrix3i>& symmetries)
{
    struct Known {
        int n, D;
        std::vector<Eigen::Matrix3i> symmetries;
        std::shared_ptr<const GridOrbits> orbits;
    };
    static std::mutex mutex;
    static std::vector<Known> known;
    {
        std::lock_guard lock(mutex);
        for (const auto& k : known)
            if (k.n == n && k.D == D && k.symmetries == symmetries) return k.orbits;
    }
    auto found = std::make_shared<const GridOrbits>(find_orbits(n, D, symmetries));
    std::lock_guard lock(mutex);
    if (known.size() >= 16) known.erase(known.begin());
    known.push_back({n, D, symmetries, found});
    return found;
}

} // namespace

ZoneGrid::ZoneGrid(const Dispersion& dispersion, const Eigen::Matrix3d& b, int n,
                   const std::vector<Eigen::Matrix3i>& symmetries, int threads)
    : n_(std::max(2, n + n % 2)), D_(dispersion.dimension())
{
    const auto grid = grid_orbits(n_, D_, symmetries);
    const std::vector<std::size_t>& orbits = grid->orbits;
    const std::size_t total = grid->orbit_of.size();
    evaluated_ = orbits.size();
    const int branches = dispersion.branches();
    std::vector<std::vector<double>> values(orbits.size());
    ParallelFor pool;
    pool.run(orbits.size(), threads, [&](int, std::size_t begin, std::size_t end) {
        for (std::size_t o = begin; o < end && (o % 64 || pool.keep_going()); ++o)
            values[o] = dispersion.omega2(b * fraction(orbits[o]));
    });
    throw_if_interrupted();
    lowest_.resize(total);
    minimum_.assign(static_cast<std::size_t>(branches), INFINITY);
    minimum_at_.assign(static_cast<std::size_t>(branches), 0);
    for (std::size_t i = 0; i < total; ++i) {
        const auto& v = values[grid->orbit_of[i]];
        lowest_[i] = v[0];
        for (std::size_t br = 0; br < v.size(); ++br)
            if (v[br] < minimum_[br]) minimum_[br] = v[br], minimum_at_[br] = i;
    }
}

Eigen::Vector3d ZoneGrid::fraction(std::size_t index) const { return centred(index, n_, D_).cast<double>() / n_; }

std::size_t ZoneGrid::gamma_index() const { return index_of(Eigen::Vector3i::Zero(), n_, D_); }

std::pair<double, std::size_t> ZoneGrid::branch_minimum(int branch) const
{
    return {minimum_[static_cast<std::size_t>(branch)], minimum_at_[static_cast<std::size_t>(branch)]};
}

std::vector<std::size_t> ZoneGrid::valleys(int count) const
{
    // The grid's local minima, in index order: x fastest, each axis wrapped at its ends.
    const std::size_t n = static_cast<std::size_t>(n_), ny = D_ > 1 ? n : 1, nz = D_ > 2 ? n : 1;
    auto around = [](std::size_t c, std::size_t extent) {
        return std::array<std::size_t, 3>{(c + extent - 1) % extent, c, (c + 1) % extent};
    };
    std::vector<std::size_t> floors;
    const std::size_t gamma = gamma_index();
    for (std::size_t z = 0; z < nz; ++z)
        for (std::size_t y = 0; y < ny; ++y)
            for (std::size_t x = 0; x < n; ++x) {
                const std::size_t i = x + n * (y + n * z);
                if (i == gamma) continue;
                const double v = lowest_[i];
                bool floor = true;
                for (std::size_t zz : around(z, nz))
                    for (std::size_t yy : around(y, ny))
                        for (std::size_t xx : around(x, n)) floor = floor && lowest_[xx + n * (yy + n * zz)] >= v;
                if (floor) floors.push_back(i);
            }
    std::sort(floors.begin(), floors.end(), [&](std::size_t a, std::size_t b) { return lowest_[a] < lowest_[b]; });
    std::vector<std::size_t> distinct;
    for (std::size_t i : floors) {
        if (static_cast<int>(distinct.size()) == count) break;
        if (!distinct.empty() && std::abs(lowest_[i] - lowest_[distinct.back()]) <= 1e-12 * std::abs(lowest_[i]))
            continue;
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
            auto [x, fx] =
                boost::math::tools::brent_find_minima(along, f[axis] - reach, f[axis] + reach, 20, iterations);
            if (fx < value) value = fx, f[axis] = x;
        }
    return {f, value};
}

} // namespace sphkern
