// The pair list that lasts (particles/engine/pair_list.hpp) against a fresh search of the
// moved set by the pass that takes each pair once, which the engine tests hold to the gather
// and to brute force.
#include "helpers.hpp"
#include "lattices/lattice.hpp"
#include "pair_test_sets.hpp"
#include "particles/engine/neighbour_gather.hpp"
#include "particles/engine/pair_list.hpp"
#include "particles/engine/symmetric_pair_pass.hpp"
#include "particles/sources/lattice_particles.hpp"
#include "particles/sources/poisson_particles.hpp"

#include <boost/random/mersenne_twister.hpp>
#include <boost/random/uniform_on_sphere.hpp>
#include <boost/random/uniform_real_distribution.hpp>
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <cmath>
#include <string>
#include <vector>

using namespace sphkern;

namespace {

// Per particle (the set's order): sum_j w(r / R) and sum_j w'(r / R) (x_j - x_i) / r over the
// neighbours within R, w(q) = (1 - q^2)^3, and the neighbours counted, each pair once by
// `pass` (a PairList's or the symmetric pass on `grid`).
struct PairSums {
    std::vector<double> sums; // five a particle
};
template <class Pass>
PairSums sums_of(const NeighbourGrid& grid, std::size_t particles, double reach, int threads, const Pass& pass)
{
    std::vector<double> by_point(5 * (grid.points() + 1));
    pass(by_point.data(), [&](std::size_t p, Neighbours& nb, double* cluster_sums) {
        std::vector<double> theirs[5];
        for (auto& v : theirs) v.assign(nb.count, 0.0);
        for (std::size_t j = 0; j < nb.count; ++j) {
            const double r = std::sqrt(nb.r2[j]), q = r / reach, u = 1 - q * q, slope = -6 * q * u * u / r;
            const double t[5] = {u * u * u, slope * nb.dx[j], slope * nb.dy[j], slope * nb.dz[j], 1};
            for (int a = 0; a < 5; ++a) by_point[5 * p + a] += t[a];
            // The other particle's: the same value and count, the opposite gradient.
            theirs[0][j] = t[0], theirs[1][j] = -t[1], theirs[2][j] = -t[2], theirs[3][j] = -t[3], theirs[4][j] = 1;
        }
        add_to_pairs<5>(nb, {theirs[0].data(), theirs[1].data(), theirs[2].data(), theirs[3].data(), theirs[4].data()},
                        cluster_sums);
    });
    PairSums out{std::vector<double>(5 * particles)};
    for_each_visited(grid, threads, [&](std::size_t p, std::size_t i) {
        for (int a = 0; a < 5; ++a) out.sums[5 * i + a] = by_point[5 * p + a];
    });
    return out;
}

PairSums fresh_search(const ParticleSet& set, double reach, int threads)
{
    const NeighbourGrid grid(set, reach, threads);
    return sums_of(grid, set.size(), reach, threads, [&](double* sums, const auto& visit) {
        symmetric_pair_pass<5>(grid, set.name, {search_reach(reach), nullptr, nullptr, true, ""}, threads, sums, visit);
    });
}

PairSums listed(const PairList& list, std::size_t particles, int threads)
{
    return sums_of(list.grid(), particles, list.support(), threads,
                   [&](double* sums, const auto& visit) { list.pass<5>(nullptr, threads, sums, visit); });
}

// Every particle moved by up to `most` in a random direction (the first by exactly `most`),
// and wrapped into the box.
ParticleSet moved(ParticleSet set, double most, std::uint64_t seed)
{
    boost::random::mt19937_64 engine(seed);
    boost::random::uniform_real_distribution<double> length(0, most);
    boost::random::uniform_on_sphere<double> direction(set.dimension);
    for (std::size_t i = 0; i < set.size(); ++i) {
        const std::vector<double> d = direction(engine);
        const double l = i == 0 ? most : length(engine);
        set.x[i] += l * d[0], set.y[i] += l * d[1];
        if (set.dimension == 3) set.z[i] += l * d[2];
    }
    if (set.box) wrap_into_box(set);
    return set;
}

double worst_difference(const std::vector<double>& a, const std::vector<double>& b, double& scale)
{
    double worst = 0;
    scale = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
        worst = std::max(worst, std::abs(a[i] - b[i])), scale = std::max(scale, std::abs(b[i]));
    return worst;
}

} // namespace

TEST_CASE("a pair list that lasts gives the sums of a fresh search of the moved set (1e-13) with the same pairs, the "
          "same bits on 1, 2 and 7 threads, and holds only while no particle has moved half its skin")
{
    for (const test::PairTestSet& c : test::pair_test_sets(3)) {
        CAPTURE(c.name);
        // Built with no skin and read where it was built: the symmetric pass's very sums.
        const PairList exact(c.set, c.reach, 0.0, 1);
        CHECK(listed(exact, c.set.size(), 1).sums == fresh_search(c.set, c.reach, 1).sums);
        // Kept while the particles move by up to just under half the skin (across the periodic sides too).
        PairList lasting(c.set, c.reach, 0.3 * c.reach, 1);
        const double skin = lasting.skin(); // less where the box is narrow
        CHECK(skin > 0.15 * c.reach);
        const ParticleSet after = moved(c.set, 0.499 * skin, 17);
        REQUIRE(lasting.follow(after));
        const PairSums kept = listed(lasting, c.set.size(), 1), fresh = fresh_search(after, c.reach, 1);
        double scale = 0;
        const double worst = worst_difference(kept.sums, fresh.sums, scale);
        CHECK(scale > 1);
        CHECK(worst < 1e-13 * scale);
        // Every particle has the same neighbours (their count is an integer well inside a double's).
        std::size_t same = 0;
        double neighbours = 0;
        for (std::size_t i = 0; i < c.set.size(); ++i)
            same += kept.sums[5 * i + 4] == fresh.sums[5 * i + 4], neighbours += fresh.sums[5 * i + 4];
        CHECK(same == c.set.size());
        CHECK(static_cast<double>(lasting.listed_pairs()) > 0.6 * neighbours); // the skin's pairs too
        for (int threads : {2, 7}) {
            PairList many(c.set, c.reach, skin, threads);
            REQUIRE(many.follow(after));
            CHECK(listed(many, c.set.size(), threads).sums == kept.sums);
        }
        // One particle half a skin and a little more from where the list was built: built again.
        CHECK_FALSE(lasting.follow(moved(c.set, 0.501 * skin, 17)));
        lasting.rebuild(after);
        CHECK(listed(lasting, c.set.size(), 1).sums == listed(PairList(after, c.reach, skin, 1), c.set.size(), 1).sums);
    }
}

TEST_CASE("a pair list names two particles that its moves brought to one position")
{
    PoissonSpec spec;
    spec.dimension = 3, spec.count = 500, spec.seed = 9;
    ParticleSet set = poisson_particles(spec);
    const double reach = 0.2;
    set.x[7] = set.x[3] + 0.01, set.y[7] = set.y[3], set.z[7] = set.z[3];
    PairList list(set, reach, 0.1, 1);
    set.x[7] = set.x[3];
    REQUIRE(list.follow(set));
    const auto run = [&] { listed(list, set.size(), 1); };
    CHECK_THROWS_WITH_AS(run(), doctest::Contains("particles 3 and 7 are at the same position"), CoincidentParticles);
}
