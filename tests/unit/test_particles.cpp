// Particle sets: every measure against a brute-force O(N^2) sum over periodic images
// (variable h and volumes, periodic and free, 2D and 3D), the lattice limit against the
// shell sums of the lattice code, the exact Poisson limits, Voronoi volumes against a_p,
// determinism, and the readers' round trips and refusals.
#include "analysis/site_errors.hpp"
#include "helpers.hpp"
#include "lattices/rectangular_cell.hpp"
#include "pair_test_sets.hpp"
#include "particles/engine/neighbour_gather.hpp"
#include "particles/engine/neighbour_grid.hpp"
#include "particles/engine/pair_pass.hpp"
#include "particles/engine/symmetric_pair_pass.hpp"
#include "particles/formats/particle_files.hpp"
#include "particles/particle_analysis.hpp"
#include "particles/sources/lattice_particles.hpp"
#include "particles/sources/poisson_particles.hpp"
#include "particles/tiled_set.hpp"
#include "requests/particles_report.hpp"
#include "support/error.hpp"
#include "support/process/block_random.hpp"
#include "support/process/parallel_for.hpp"

#include <boost/random/mersenne_twister.hpp>
#include <boost/random/uniform_real_distribution.hpp>
#include <doctest/doctest.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <numbers>
#include <numeric>
#include <random>

using namespace sphkern;
using sphkern::test::shipped_kernel;

namespace {

// Every measure of particle i written out from the definitions: all pairs, every periodic
// image in the 3^D neighbouring boxes, the support edge inside.
struct Brute {
    double e0, eps_rho, eps_gradp;
    Eigen::Vector3d e1, m1;
    Eigen::Matrix3d E;
    int neighbours;
};

Brute brute_force(const Kernel& kernel, const ParticleSet& set, const MeasureInputs& in, std::size_t i,
                  const Eigen::Vector3d& g)
{
    const int dim = set.dimension;
    const double h = in.h[i], k = h / in.spacing, R = kernel.support(), hd = std::pow(h, dim);
    const std::span<const double> mass = in.mass.empty() ? in.volume.values : in.mass; // rho0 = 1 when empty
    Brute b{in.volume[i] * kernel.w(0, dim, k) / hd - 1,
            mass[i] * kernel.w(0, dim, k) / hd / in.rho0 - 1,
            0,
            Eigen::Vector3d::Zero(),
            Eigen::Vector3d::Zero(),
            -Eigen::Matrix3d::Identity(),
            0};
    if (dim == 2) b.E(2, 2) = 0;
    const int images = set.box ? 1 : 0;
    for (std::size_t j = 0; j < set.size(); ++j)
        for (int a = -images; a <= images; ++a)
            for (int c = -images; c <= images; ++c)
                for (int e = (dim == 3 ? -images : 0); e <= (dim == 3 ? images : 0); ++e) {
                    Eigen::Vector3d shift = Eigen::Vector3d::Zero();
                    if (set.box) shift = set.box->edges * Eigen::Vector3d(a, c, e);
                    const Eigen::Vector3d r = set.position(j) + shift - set.position(i);
                    const double d = r.norm();
                    if (d == 0 || d / h > R * (1 + 1e-12)) continue;
                    const double W = kernel.w(d / h, dim, k) / hd, dW = kernel.dw(d / h, dim, k) / hd / h;
                    const Eigen::Vector3d grad = -dW * r / d;
                    b.e0 += in.volume[j] * W;
                    b.eps_rho += mass[j] * W / in.rho0;
                    b.m1 += in.volume[j] * W * r / h;
                    b.e1 += h * in.volume[j] * grad;
                    b.E += in.volume[j] * r * grad.transpose();
                    b.neighbours += 1;
                }
    b.eps_gradp = g.dot(b.E * g);
    return b;
}

ParticleSet random_set(int dim, std::size_t n, bool periodic, std::uint64_t seed)
{
    PoissonSpec spec;
    spec.dimension = dim, spec.count = n, spec.seed = seed;
    spec.box = Eigen::Vector3d(1.0, 1.3, 0.9);
    auto set = poisson_particles(spec);
    if (!periodic) set.box.reset();
    return set;
}

// Random h, volumes and masses, and the inputs that view them.
struct VariedInputs {
    std::vector<double> h, volume, mass;
    MeasureInputs in;
    VariedInputs(const VariedInputs&) = delete;
    VariedInputs(const ParticleSet& set, double h0, std::uint64_t seed)
    {
        boost::random::mt19937_64 engine(seed);
        boost::random::uniform_real_distribution<double> u(0.7, 1.3);
        const double v0 = (set.dimension == 3 ? 1.17 : 1.3) / static_cast<double>(set.size());
        for (std::size_t i = 0; i < set.size(); ++i) {
            h.push_back(h0 * u(engine));
            volume.push_back(v0 * u(engine));
            mass.push_back(2.5 * v0 * u(engine));
        }
        in.h = PerParticleView::of(h), in.volume = PerParticleView::of(volume), in.mass = mass;
        in.rho0 = 2.5;
        in.spacing = std::pow(v0, 1.0 / set.dimension);
        in.depth = 3;
    }
};

// One measure of every particle.
std::vector<double> values_of(const ParticleMeasures& m, double MeasureRecord::*field)
{
    std::vector<double> values;
    for (const MeasureRecord& r : m.scalars) values.push_back(r.*field);
    return values;
}

void check_against_brute_force(const Kernel& kernel, const ParticleSet& set, const MeasureInputs& in)
{
    const auto m = measure_particles(kernel, set, in);
    const Eigen::Vector3d g = set.gravity;
    int larger = 0;
    for (std::size_t i = 0; i < set.size(); i += 7) {
        const Brute b = brute_force(kernel, set, in, i, g);
        CHECK(m.scalars[i].neighbours == b.neighbours);
        CHECK(m.scalars[i].e0 == doctest::Approx(b.e0).epsilon(1e-12));
        CHECK(m.eps_rho_of(i) == doctest::Approx(b.eps_rho).epsilon(1e-12));
        CHECK(m.scalars[i].eps_gradp == doctest::Approx(b.eps_gradp).epsilon(1e-12));
        const Eigen::Vector3d e1(m.e1[i][0], m.e1[i][1], m.e1[i][2]);
        CHECK(m.scalars[i].eps_gradp_sum == doctest::Approx(b.eps_gradp + 2 * in.depth * e1.dot(g)).epsilon(1e-12));
        for (int a = 0; a < 3; ++a) {
            CHECK(std::abs(m.e1[i][static_cast<std::size_t>(a)] - b.e1[a]) < 1e-11);
            CHECK(std::abs(m.m1[i][static_cast<std::size_t>(a)] - b.m1[a]) < 1e-11);
        }
        const auto& E = m.E[i];
        const double stored[6] = {b.E(0, 0), b.E(1, 1), b.E(2, 2), b.E(0, 1), b.E(0, 2), b.E(1, 2)};
        for (int c = 0; c < 6; ++c) CHECK(std::abs(E[static_cast<std::size_t>(c)] - stored[c]) < 1e-11);
        // The magnitudes the statistics read, against the brute force's own vectors and tensor.
        CHECK(m.scalars[i].e1_norm == doctest::Approx(b.e1.norm()).epsilon(1e-10));
        CHECK(m.scalars[i].m1_norm == doctest::Approx(b.m1.norm()).epsilon(1e-10));
        CHECK(std::abs(m.scalars[i].E_norm - b.E.norm()) < 1e-10); // E is symmetric: r and grad W are parallel
        larger += b.neighbours > 10;
    }
    CHECK(larger > 0); // the sets are dense enough for the sums to mean something
}

} // namespace

TEST_CASE("every measure equals a brute-force sum: 2D and 3D, periodic and free, variable h, volumes and masses")
{
    const auto cubic = shipped_kernel("cubic_bspline");
    const auto wendland = shipped_kernel("wendland_c2");
    for (int dim : {2, 3})
        for (bool periodic : {true, false}) {
            CAPTURE(dim);
            CAPTURE(periodic);
            const auto set = random_set(dim, dim == 3 ? 2500 : 1500, periodic, 11 + dim);
            const double h0 = dim == 3 ? 0.09 : 0.06;
            check_against_brute_force(cubic, set, VariedInputs(set, h0, 5).in);
            check_against_brute_force(wendland, set, VariedInputs(set, h0, 6).in);
        }
}

TEST_CASE("every measure equals a brute-force sum with one volume for all, with and without masses")
{
    // One volume for every particle takes the engine's path without per-neighbour volumes.
    const auto kernel = shipped_kernel("cubic_bspline");
    for (int dim : {2, 3}) {
        CAPTURE(dim);
        const auto set = random_set(dim, dim == 3 ? 2500 : 1500, true, 21 + dim);
        VariedInputs varied(set, dim == 3 ? 0.09 : 0.06, 7);
        std::fill(varied.volume.begin(), varied.volume.end(), varied.volume.front());
        check_against_brute_force(kernel, set, varied.in);
        varied.in.mass = {}, varied.in.rho0 = 1;
        check_against_brute_force(kernel, set, varied.in);
    }
}

TEST_CASE("on an unperturbed periodic lattice block every particle has the lattice's eps_rho and eps_gradP")
{
    const auto kernel = shipped_kernel("cubic_bspline");
    for (const std::string name : {"triangular", "square", "fcc", "bcc", "hcp", "sc", "honeycomb"}) {
        CAPTURE(name);
        const auto lattice = name == "honeycomb" ? load_lattice(SPHKERN_SOURCE_DIR "/lattices/examples/honeycomb.json")
                                                 : load_lattice(name);
        const double k = 1.13;
        LatticeBlockSpec spec;
        spec.cells = lattice.dimension == 2 ? std::array<long long, 3>{12, 12, 1} : std::array<long long, 3>{7, 7, 7};
        const auto set = lattice_particles(lattice, spec);
        ParticleRequest request;
        request.smoothing = {SmoothingRule::k, k, 0};
        const auto answer = analyse_particles(kernel, set, request);
        const double a_p = lattice.volume_coefficient("voronoi");
        CHECK(answer.mean_volume == doctest::Approx(a_p).epsilon(1e-13));
        const auto sites = errors_per_site(kernel, lattice, every_site(lattice), a_p, lattice.gravity, k);
        const auto& m = *answer.measures;
        double worst_rho = 0, worst_gradp = 0, worst_e1 = 0;
        for (std::size_t i = 0; i < set.size(); ++i) {
            const auto& site = *sites[i % static_cast<std::size_t>(lattice.sites())];
            const auto values = site.at(k);
            worst_rho = std::max(worst_rho, std::abs(m.scalars[i].e0 - values.eps_rho));
            worst_gradp = std::max(worst_gradp, std::abs(m.scalars[i].eps_gradp - values.eps_gradp));
            // e1 = h sum V grad_i W = -k m1 of the lattice code (its first moment, times d^(D+1)).
            const Eigen::Vector3d first = site.tensor(k).first_moment;
            for (int a = 0; a < 3; ++a)
                worst_e1 = std::max(worst_e1, std::abs(m.e1[i][static_cast<std::size_t>(a)] + k * first[a]));
            REQUIRE(m.scalars[i].neighbours == values.neighbours);
        }
        CHECK(worst_rho < 1e-12);
        CHECK(worst_gradp < 1e-12);
        CHECK(worst_e1 < 1e-12);
    }
}

TEST_CASE("Voronoi volumes: a lattice's cell is a_p d^D to 1e-12, and a random set's cells fill its box")
{
    for (const std::string name : {"triangular", "fcc", "hcp", "bcc", "hex_prism"}) {
        CAPTURE(name);
        const auto lattice = load_lattice(name);
        LatticeBlockSpec spec;
        spec.cells = lattice.dimension == 2 ? std::array<long long, 3>{6, 5, 1} : std::array<long long, 3>{4, 3, 5};
        const auto set = lattice_particles(lattice, spec);
        const double a_p = lattice.volume_coefficient("voronoi");
        for (double v : voronoi_volumes(set)) REQUIRE(std::abs(v - a_p) < 1e-12 * a_p);
    }
    for (int dim : {2, 3}) {
        const auto set = random_set(dim, 3000, true, 3);
        const auto v = voronoi_volumes(set);
        const double total = std::accumulate(v.begin(), v.end(), 0.0);
        CHECK(total == doctest::Approx(set.box->volume(dim)).epsilon(1e-10));
    }
}

namespace {

// The integral of W^2 over D-space at h = 1, by composite Simpson over q (independent of
// the statistics code).
double integral_of_w_squared(const Kernel& kernel, int dim)
{
    const int n = 20000;
    const double R = kernel.support(), step = R / n;
    double sum = 0;
    for (int i = 0; i <= n; ++i) {
        const double q = i * step, w = kernel.w(q, dim, 1.0);
        const double f = w * w * (dim == 3 ? 4 * std::numbers::pi * q * q : 2 * std::numbers::pi * q);
        sum += f * (i == 0 || i == n ? 1 : (i % 2 ? 4 : 2));
    }
    return sum * step / 3;
}

} // namespace

TEST_CASE("Poisson sets: the mean of e0 is V W(0) - 1/N and its variance V int W^2 - 1/N (exact limits)")
{
    const auto kernel = shipped_kernel("wendland_c2");
    for (int dim : {2, 3}) {
        CAPTURE(dim);
        // Sixteen independent sets: the spread of their means is the standard error.
        const std::size_t n = 5000;
        std::vector<double> means, variances;
        double expected_mean = 0, expected_variance = 0;
        for (std::uint64_t seed = 1; seed <= 16; ++seed) {
            PoissonSpec spec;
            spec.dimension = dim, spec.count = n, spec.seed = seed;
            const auto set = poisson_particles(spec);
            ParticleRequest request;
            request.smoothing = {SmoothingRule::nh, 60, 0};
            const auto answer = analyse_particles(kernel, set, request);
            const auto& s = answer.points[0].statistics[0];
            REQUIRE(s.first == "e0");
            means.push_back(s.second.mean);
            variances.push_back(s.second.std * s.second.std);
            const double h = answer.h[0], V = answer.mean_volume, N = static_cast<double>(n);
            expected_mean = V * kernel.w(0, dim, 1.0) / std::pow(h, dim) - 1 / N;
            expected_variance = V * integral_of_w_squared(kernel, dim) / std::pow(h, dim) - 1 / N;
        }
        auto mean_and_error = [](const std::vector<double>& v) {
            const double m = std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
            double s = 0;
            for (double x : v) s += (x - m) * (x - m);
            return std::pair{m, std::sqrt(s / static_cast<double>(v.size() - 1) / static_cast<double>(v.size()))};
        };
        const auto [mean, mean_error] = mean_and_error(means);
        const auto [variance, variance_error] = mean_and_error(variances);
        MESSAGE("D = ", dim, ": mean e0 ", mean, " +- ", mean_error, " (exact ", expected_mean, "), variance ",
                variance, " +- ", variance_error, " (exact ", expected_variance, ")");
        // Seven standard errors (Student's t with 15 degrees of freedom: p < 1e-5); the seeds
        // are fixed and Boost's generator portable, so the outcome is the same on every machine.
        CHECK(std::abs(mean - expected_mean) < 7 * mean_error);
        CHECK(std::abs(variance - expected_variance) < 7 * variance_error);
        CHECK(mean_error < 0.05 * expected_mean); // the test can tell a wrong limit
    }
}

LatticeBlockSpec perturbed_block(long long cells, std::uint64_t seed)
{
    LatticeBlockSpec spec;
    spec.cells = {cells, cells, cells};
    spec.sigma = 0.05;
    spec.seed = seed;
    return spec;
}

TEST_CASE("statistics over several blocks: exact percentiles, and the same bits on 1, 2 and 7 threads")
{
    auto reference = [](std::vector<double> v, double p) {
        std::sort(v.begin(), v.end());
        const double rank = p * static_cast<double>(v.size() - 1);
        const auto lo = static_cast<std::size_t>(std::floor(rank));
        return v[lo] + (rank - static_cast<double>(lo)) * (v[std::min(lo + 1, v.size() - 1)] - v[lo]);
    };
    std::mt19937_64 random(11);
    std::normal_distribution<double> normal(0.0, 1e-3);
    // Spread values of both signs (zeros of both signs among them), and crowded ones: integers
    // in one narrow range, most of them in one bucket of the selection's histogram.
    std::vector<double> spread(300007), crowded(200003);
    for (std::size_t i = 0; i < spread.size(); ++i)
        spread[i] = i % 1000 == 0 ? (i % 2000 ? -0.0 : 0.0) : normal(random);
    for (auto& v : crowded) v = 58.0 + static_cast<double>(random() % 5);
    // Neighbouring doubles on both sides of 1 (where a key's high bits carry), between two far
    // values: the cluster lies in one bucket of the histogram, its keys straddle a power of two.
    std::vector<double> straddling{0.7, 2.0};
    for (int j = -60000; j < 60000; ++j) straddling.push_back(std::nextafter(1.0, j < 0 ? 0.0 : 2.0) + j * 0x1p-52);
    std::shuffle(straddling.begin(), straddling.end(), random);
    for (const auto* values : {&spread, &crowded, &straddling}) {
        const auto one = summarise(*values, 1);
        CHECK(one.p1 == reference(*values, 0.01));
        CHECK(one.p50 == reference(*values, 0.5));
        CHECK(one.p99 == reference(*values, 0.99));
        CHECK(one.min == *std::min_element(values->begin(), values->end()));
        CHECK(one.max == *std::max_element(values->begin(), values->end()));
        double sum = 0;
        for (double v : *values) sum += v;
        CHECK(one.mean == doctest::Approx(sum / static_cast<double>(values->size())).epsilon(1e-12));
        const auto bins = histogram(*values, 17, 1);
        std::size_t total = 0;
        for (auto c : bins.counts) total += c;
        CHECK(total == values->size());
        for (int threads : {2, 7}) {
            CAPTURE(threads);
            const auto other = summarise(*values, threads);
            CHECK(std::memcmp(&one, &other, sizeof one) == 0);
            CHECK(histogram(*values, 17, threads).counts == bins.counts);
        }
    }
}

TEST_CASE("parallel sums add fixed blocks in block order: the same bits on 1, 2 and 7 threads")
{
    const std::size_t n = 7 * particle_block_size + 321;
    std::vector<double> terms(n);
    std::mt19937_64 random(2);
    for (auto& t : terms) t = std::ldexp(static_cast<double>(random() % 1000000), -static_cast<int>(random() % 60));
    // The reference: each block summed in order, then the blocks in order.
    double expected = 0;
    for (std::size_t b = 0; b * particle_block_size < n; ++b) {
        double block = 0;
        for (std::size_t i = b * particle_block_size; i < std::min(n, (b + 1) * particle_block_size); ++i)
            block += terms[i];
        expected += block;
    }
    for (int threads : {1, 2, 7}) {
        CAPTURE(threads);
        CHECK(parallel_sum(n, threads, [&](std::size_t i) { return terms[i]; }) == expected);
        // Bad items in blocks 3 and 5 (and late in block 3): the lowest is found.
        const std::size_t early = 3 * particle_block_size + 17, later = 5 * particle_block_size + 1;
        const auto first =
            first_index_where(n, threads, [&](std::size_t i) { return i == early || i == early + 100 || i == later; });
        REQUIRE(first.has_value());
        CHECK(*first == early);
    }
}

TEST_CASE("sources, validation and the neighbour grid are the same on 1, 2 and 7 threads")
{
    // Over seven random blocks of particles, so that seven threads each draw one at least.
    PoissonSpec poisson;
    poisson.dimension = 3, poisson.count = 7 * random_block_size + 123, poisson.seed = 4;
    const auto one = poisson_particles(poisson, 1);
    LatticeBlockSpec block;
    block.cells = {80, 80, 80}, block.sigma = 0.4, block.seed = 3;
    const auto lattice = load_lattice("fcc");
    const auto disturbed = lattice_particles(lattice, block, 1);
    REQUIRE(disturbed.size() > 7 * random_block_size);
    const NeighbourGrid grid(one, 0.03, 1);
    for (int threads : {2, 7}) {
        CAPTURE(threads);
        const auto other = poisson_particles(poisson, threads);
        CHECK(other.x == one.x);
        CHECK(other.y == one.y);
        CHECK(other.z == one.z);
        const auto moved = lattice_particles(lattice, block, threads);
        CHECK(moved.x == disturbed.x);
        CHECK(moved.z == disturbed.z);
        const NeighbourGrid built(one, 0.03, threads);
        REQUIRE(built.points() == grid.points());
        REQUIRE(built.bins() == grid.bins());
        bool same = true;
        for (std::size_t p = 0; p < grid.points(); ++p)
            same =
                same && built.source(p) == grid.source(p) && built.x()[p] == grid.x()[p] && built.z()[p] == grid.z()[p];
        for (std::size_t b = 0; b <= grid.bins(); ++b) same = same && built.bin_begin(b) == grid.bin_begin(b);
        CHECK(same);
    }
    // The grid holds each particle once and each bin's points inside it, sorted by bin.
    std::vector<int> seen(one.size(), 0);
    for (std::size_t p = 0; p < grid.points(); ++p)
        if (grid.visited(p)) ++seen[grid.source(p)];
    CHECK(std::all_of(seen.begin(), seen.end(), [](int s) { return s == 1; }));
    // Two bad particles in different blocks: the lowest id is named on any thread count.
    auto bad = one;
    bad.y[6 * particle_block_size + 5] = NAN, bad.y[2 * particle_block_size + 9] = INFINITY;
    const std::string named = fmt::format("particle {} has a non-finite", 2 * particle_block_size + 9);
    for (int threads : {1, 7})
        CHECK_THROWS_WITH_AS(validate_particle_set(bad, threads), doctest::Contains(named.c_str()), Error);
}

TEST_CASE("a perturbed lattice is the same for a seed, and results do not depend on the thread count")
{
    const auto lattice = load_lattice("fcc");
    LatticeBlockSpec spec = perturbed_block(8, 7);
    const auto a = lattice_particles(lattice, spec), b = lattice_particles(lattice, spec);
    CHECK(a.x == b.x);
    CHECK(a.z == b.z);
    spec.seed = 8;
    CHECK(lattice_particles(lattice, spec).x != a.x);
    const auto kernel = shipped_kernel("morris_quintic");
    ParticleRequest request;
    request.smoothing = {SmoothingRule::k, 1.0, 0};
    request.threads = 1;
    const auto one = analyse_particles(kernel, a, request);
    request.threads = 3;
    const auto three = analyse_particles(kernel, a, request);
    CHECK(values_of(*one.measures, &MeasureRecord::e0) == values_of(*three.measures, &MeasureRecord::e0));
    CHECK(values_of(*one.measures, &MeasureRecord::eps_gradp) == values_of(*three.measures, &MeasureRecord::eps_gradp));
    // The disorder shows: the spread of e0 is far above rounding.
    CHECK(one.points[0].statistics[0].second.std > 1e-4);
}

TEST_CASE("particles: a stated gravity direction gives eps_gradp = g.E.g with that g, not the set's")
{
    const auto set = lattice_particles(load_lattice("fcc"), perturbed_block(6, 3));
    const auto kernel = shipped_kernel("cubic_bspline");
    ParticleRequest request;
    request.smoothing = {SmoothingRule::k, 1.2, 0};
    request.depth = 2.5;
    for (const Eigen::Vector3d& g : {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 3, 4)}) {
        CAPTURE(g.transpose());
        request.gravity = g;
        const auto answer = analyse_particles(kernel, set, request);
        const auto& m = *answer.measures;
        const Eigen::Vector3d u = g.normalized();
        double largest_change = 0;
        for (std::size_t i = 0; i < m.size(); ++i) {
            const auto& E = m.E[i]; // xx, yy, zz, xy, xz, yz
            const double expected = u.x() * u.x() * E[0] + u.y() * u.y() * E[1] + u.z() * u.z() * E[2] +
                                    2 * (u.x() * u.y() * E[3] + u.x() * u.z() * E[4] + u.y() * u.z() * E[5]);
            CHECK(m.scalars[i].eps_gradp == doctest::Approx(expected).epsilon(1e-12).scale(1));
            // The sum form at depth D: eps_gradp + 2 D (e1 . g).
            const double e1_g = u.x() * m.e1[i][0] + u.y() * m.e1[i][1] + u.z() * m.e1[i][2];
            CHECK(m.scalars[i].eps_gradp_sum ==
                  doctest::Approx(expected + 2 * request.depth * e1_g).epsilon(1e-12).scale(1));
            largest_change = std::max(largest_change, std::abs(m.scalars[i].eps_gradp - E[2])); // the set's g is -z
        }
        CHECK(largest_change > 1e-3);
    }
}

TEST_CASE("the neighbour number gives h: a Poisson set's mean neighbour count is N_H (N - 1)/N")
{
    const auto kernel = shipped_kernel("cubic_bspline");
    PoissonSpec spec;
    spec.dimension = 3, spec.count = 30000, spec.seed = 2;
    const auto set = poisson_particles(spec);
    ParticleRequest request;
    request.smoothing = {SmoothingRule::nh, 57, 0};
    const auto answer = analyse_particles(kernel, set, request);
    CHECK(answer.points[0].nh == doctest::Approx(57).epsilon(1e-12));
    // Each count is Poisson-distributed (variance 57): the mean of 30000 is within 0.5 of 57 at 10 sigma.
    CHECK(std::abs(answer.points[0].mean_neighbours - 57) < 0.5);
    CHECK(eta_for_neighbour_number(neighbour_number(1.3, 2, 2), 2, 2) == doctest::Approx(1.3).epsilon(1e-14));
}

TEST_CASE("files: CSV and VTK round trips, DualSPHysics-style CSV, and one-line refusals")
{
    const auto dir = std::filesystem::temp_directory_path() / ("sphkern-particles-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const auto kernel = shipped_kernel("wendland_c2");
    const auto set = random_set(3, 800, true, 4);
    ParticleRequest request;
    request.smoothing = {SmoothingRule::eta, 1.3, 0};
    const auto answer = analyse_particles(kernel, set, request);
    {
        std::ofstream csv(dir / "out.csv"), vtk(dir / "out.vtk");
        write_particle_csv(csv, set, answer);
        write_particle_vtk(vtk, set, answer);
    }
    for (const char* file : {"out.csv", "out.vtk"}) {
        CAPTURE(file);
        const auto back = read_particle_file(dir / file, {});
        REQUIRE(back.size() == set.size());
        CHECK(back.dimension == 3);
        CHECK(back.x == set.x);
        CHECK(back.y == set.y);
        CHECK(back.z == set.z);
        REQUIRE(back.h.size() == answer.h.size());
        for (std::size_t i = 0; i < back.h.size(); ++i) CHECK(back.h[i] == answer.h[i]);
    }
    {
        std::ofstream dual(dir / "dual.csv");
        dual << "# a comment line\nPos.x [m];Pos.y [m];Pos.z [m];Idp;Rhop [kg/m^3];\n"
             << "0.5;0.25;1.0;0;1000.5;\n1.5;0.25;1.0;1;999.0;\n2.5;0.25;3.0;2;998.0;\n";
    }
    ParticleFileOptions two;
    two.dimension = 2;
    const auto dual = read_particle_file(dir / "dual.csv", two);
    CHECK(dual.dimension == 2);
    CHECK(dual.x == ParticleValues{0.5, 1.5, 2.5});
    CHECK(dual.y == ParticleValues{1.0, 1.0, 3.0}); // the x-z plane
    CHECK(dual.density == ParticleValues{1000.5, 999.0, 998.0});

    auto refused = [&](const std::string& name, const std::string& text, const std::string& expected) {
        CAPTURE(name);
        {
            std::ofstream f(dir / name);
            f << text;
        }
        try {
            auto s = read_particle_file(dir / name, {});
            validate_particle_set(s);
            FAIL("accepted");
        } catch (const Error& e) {
            CHECK(e.code() == ExitCode::input);
            CHECK(std::string(e.what()).find(expected) != std::string::npos);
            CHECK(std::string(e.what()).find('\n') == std::string::npos);
        }
    };
    refused("nox.csv", "a,y,z\n1,2,3\n", "no column x");
    refused("word.csv", "x,y\n1,2\n3,abc\n", "line 3, column y (particle 1): \"abc\" is not a number");
    refused("short.csv", "x,y,h\n1,2,3\n4,5\n", "line 3 (particle 1): 2 fields, expected 3");
    refused("nan.csv", "x,y\n1,2\nnan,5\n", "particle 1 has a non-finite coordinate");
    refused("h.csv", "x,y,h\n1,2,0.1\n4,5,-1\n", "the smoothing length of particle 1 is -1");
    refused("empty.csv", "", "empty.csv: no header line");
    refused("cut.vtk", "# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\nPOINTS 3 double\n1 2 3 4 5 6\n",
            "unexpected end of file");
    refused("grid.vtk", "# vtk DataFile Version 3.0\nt\nASCII\nDATASET STRUCTURED_POINTS\n",
            "expected POLYDATA or UNSTRUCTURED_GRID");
    refused("junk.h5", "not hdf5 at all", "not an HDF5 file");
    std::filesystem::remove_all(dir);
}

TEST_CASE("two particles at one position, and a box smaller than the support, are refused by name")
{
    const auto kernel = shipped_kernel("cubic_bspline");
    auto set = random_set(2, 200, true, 9);
    set.x[17] = set.x[3], set.y[17] = set.y[3];
    ParticleRequest request;
    request.smoothing = {SmoothingRule::eta, 1.2, 0};
    try {
        analyse_particles(kernel, set, request);
        FAIL("accepted");
    } catch (const Error& e) {
        CHECK(std::string(e.what()).find("particles 3 and 17 are at the same position") != std::string::npos);
    }
    const auto small = random_set(2, 50, true, 9);
    request.smoothing = {SmoothingRule::eta, 2.0, 0};
    CHECK_THROWS_WITH_AS(analyse_particles(kernel, small, request),
                         doctest::Contains("less than twice the support radius"), Error);
}

TEST_CASE("a set's statistics, read from its records a run at a time, are each measure's own, on 1 and 3 threads")
{
    // 300000 particles: runs of 65536 records on one thread and of 73728 on three (a quarter
    // of the set), several of them either way.
    PoissonSpec spec;
    spec.count = 300000, spec.seed = 5;
    const auto set = poisson_particles(spec);
    ParticleRequest request;
    request.smoothing = {SmoothingRule::nh, 20, 0};
    request.histogram_bins = 13;
    request.threads = 1;
    const auto one = analyse_particles(shipped_kernel("cubic_bspline"), set, request);
    request.threads = 3;
    const auto three = analyse_particles(shipped_kernel("cubic_bspline"), set, request);
    const auto& m = *one.measures;
    const auto& stats = one.points[0].statistics;
    REQUIRE(stats.size() == 8);
    const std::vector<double> columns[] = {values_of(m, &MeasureRecord::e0),
                                           values_of(m, &MeasureRecord::e0),
                                           values_of(m, &MeasureRecord::eps_gradp),
                                           values_of(m, &MeasureRecord::eps_gradp_sum),
                                           values_of(m, &MeasureRecord::e1_norm),
                                           values_of(m, &MeasureRecord::m1_norm),
                                           values_of(m, &MeasureRecord::E_norm)};
    std::vector<double> neighbours;
    for (const MeasureRecord& r : m.scalars) neighbours.push_back(r.neighbours);
    for (std::size_t f = 0; f < stats.size(); ++f) {
        CAPTURE(stats[f].first);
        const Summary expected = summarise(f < 7 ? columns[f] : neighbours, 1);
        CHECK(std::memcmp(&stats[f].second, &expected, sizeof expected) == 0);
        CHECK(std::memcmp(&three.points[0].statistics[f].second, &expected, sizeof expected) == 0);
    }
    REQUIRE(one.points[0].histograms.size() == 4);
    for (std::size_t f = 0; f < 4; ++f) {
        const Histogram expected = histogram(columns[f], 13, 1);
        CHECK(one.points[0].histograms[f].second.counts == expected.counts);
        CHECK(three.points[0].histograms[f].second.counts == expected.counts);
    }
}

TEST_CASE("statistics: percentiles interpolate between order statistics as numpy does")
{
    // numpy.percentile([3, 1, 4, 1, 5, 9, 2, 6], [1, 50, 99]) = [1.0, 3.5, 8.79].
    const auto s = summarise(std::vector<double>{3, 1, 4, 1, 5, 9, 2, 6});
    CHECK(s.p1 == doctest::Approx(1.0).epsilon(1e-15));
    CHECK(s.p50 == doctest::Approx(3.5).epsilon(1e-15));
    CHECK(s.p99 == doctest::Approx(8.79).epsilon(1e-14));
    CHECK(s.min == 1);
    CHECK(s.max == 9);
    CHECK(s.mean == doctest::Approx(3.875).epsilon(1e-15));
    CHECK(s.rms == doctest::Approx(std::sqrt(173.0 / 8)).epsilon(1e-15));
    CHECK(s.std == doctest::Approx(std::sqrt(173.0 / 8 - 3.875 * 3.875)).epsilon(1e-14));
}

TEST_CASE(
    "statistics: percentiles equal numpy's linear interpolation of the sorted values, for every size and with ties")
{
    // The reference sorts; summarise selects (nth_element).
    auto reference = [](std::vector<double> v, double p) {
        std::sort(v.begin(), v.end());
        const double rank = p * static_cast<double>(v.size() - 1);
        const auto lo = static_cast<std::size_t>(std::floor(rank));
        const double above = lo + 1 < v.size() ? v[lo + 1] : v[lo];
        return v[lo] + (rank - static_cast<double>(lo)) * (above - v[lo]);
    };
    std::mt19937_64 random(5);
    for (std::size_t n = 1; n <= 420; n += (n < 40 ? 1 : 37))
        for (int ties : {0, 1}) {
            CAPTURE(n);
            CAPTURE(ties);
            std::vector<double> values(n);
            for (auto& v : values)
                v = ties ? static_cast<double>(random() % 5) : static_cast<double>(random() % 100000) / 7.0;
            const auto s = summarise(values);
            CHECK(s.p1 == reference(values, 0.01));
            CHECK(s.p50 == reference(values, 0.5));
            CHECK(s.p99 == reference(values, 0.99));
        }
}

TEST_CASE(
    "the runs cut to a point's support hold every point within it once, about 3 (3D) or 2 (2D) candidates a neighbour")
{
    for (int dim : {2, 3})
        for (bool periodic : {true, false}) {
            CAPTURE(dim);
            CAPTURE(periodic);
            const auto set = random_set(dim, dim == 3 ? 3000 : 1500, periodic, 21 + dim);
            const double reach = dim == 3 ? 0.18 : 0.12;
            const NeighbourGrid grid(set, reach);
            std::size_t candidates = 0, inside = 0, missed = 0, twice = 0;
            for (std::size_t p = 0; p < grid.points(); p += 5)
                for (double r : {reach, 0.55 * reach}) {
                    std::vector<int> seen(grid.points(), 0);
                    const double at[3] = {grid.x()[p], grid.y()[p], grid.z()[p]}; // a box of one point
                    grid.for_each_run_near_box(at, at, r, [&](std::size_t first, std::size_t last) {
                        for (std::size_t j = first; j < last; ++j) seen[j] += 1;
                        candidates += last - first;
                    });
                    for (std::size_t j = 0; j < grid.points(); ++j) {
                        const double dx = grid.x()[j] - grid.x()[p], dy = grid.y()[j] - grid.y()[p],
                                     dz = grid.z()[j] - grid.z()[p];
                        const bool near = dx * dx + dy * dy + dz * dz <= r * r;
                        inside += near, missed += near && seen[j] == 0, twice += seen[j] > 1;
                    }
                }
            CHECK(missed == 0);
            CHECK(twice == 0);
            CHECK(inside > 20 * grid.points() / 5);
            // Whole rows of 3 bins a reach wide held 27/(4 pi/3) = 6.4 candidates a neighbour in
            // 3D and 9/pi = 2.9 in 2D; rows cut to the chord, at a quarter reach along x, about
            // 3.5 and 1.9.
            CHECK(static_cast<double>(candidates) < (dim == 3 ? 4.2 : 2.4) * static_cast<double>(inside));
        }
}

namespace {

// f(set, dim, periodic) on random sets of 2000 (3D) or 1000 (2D) points, periodic and free, on
// every compress path the processor can take (scalar, AVX2, AVX-512); the widest path after.
template <class F>
void on_every_path(std::uint64_t seed, const F& f)
{
    for (int path = 0; path <= static_cast<int>(widest_compress_path()); ++path)
        for (int dim : {2, 3})
            for (bool periodic : {true, false}) {
                use_compress_path(static_cast<CompressPath>(path));
                CAPTURE(path);
                CAPTURE(dim);
                CAPTURE(periodic);
                f(random_set(dim, dim == 3 ? 2000 : 1000, periodic, seed + static_cast<std::uint64_t>(dim)), dim,
                  periodic);
            }
    use_compress_path(widest_compress_path());
}

// Each point's index as its value a, to find it again among the kept neighbours.
std::vector<double> point_indices(const NeighbourGrid& grid)
{
    std::vector<double> ids(grid.points());
    std::iota(ids.begin(), ids.end(), 0.0);
    return ids;
}

// Point j within r of point p, not p itself, by brute force over the grid's points.
bool within(const NeighbourGrid& grid, std::size_t j, std::size_t p, double r)
{
    const double dx = grid.x()[j] - grid.x()[p], dy = grid.y()[j] - grid.y()[p], dz = grid.z()[j] - grid.z()[p];
    return j != p && dx * dx + dy * dy + dz * dz <= r * r;
}

} // namespace

TEST_CASE("a cluster's shared candidates hold, once each, every point within each of its particles' support")
{
    // Every path the processor can take keeps the same points.
    on_every_path(31, [](const ParticleSet& set, int dim, bool) {
        // Variable h: each particle's reach between 0.5 and 1 of the grid's.
        const double reach = dim == 3 ? 0.18 : 0.12;
        std::vector<double> reaches(set.size());
        for (std::size_t i = 0; i < set.size(); ++i) reaches[i] = reach * (0.5 + 0.5 * static_cast<double>(i % 7) / 6);
        const NeighbourGrid grid(set, reach);
        const std::vector<double> point_reaches = grid.gather(reaches);
        const std::vector<double> ids = point_indices(grid);
        ClusterCandidates cluster;
        Neighbours nb;
        std::size_t checked = 0, wrong = 0, neighbours = 0;
        for (std::size_t b = 0; b < grid.clusters(); ++b) {
            gather_cluster(grid, b, {point_reaches.data(), 0}, ids.data(), nullptr, cluster);
            std::vector<int> seen(grid.points(), 0);
            for (std::size_t c = 0; c < cluster.count; ++c) seen[static_cast<std::size_t>(cluster.a[c])] += 1;
            for (std::size_t p = grid.cluster_begin(b); p < grid.cluster_end(b); ++p) {
                if (!grid.visited(p)) continue;
                const double r = reaches[grid.source(p)];
                gather_from_cluster(grid, cluster, p, r * r, set.name, nb);
                std::vector<int> kept(grid.points(), 0);
                for (std::size_t j = 0; j < nb.count; ++j) kept[static_cast<std::size_t>(nb.a[j])] += 1;
                for (std::size_t j = 0; j < grid.points(); ++j) {
                    const bool near = within(grid, j, p, r);
                    wrong += (near && seen[j] != 1) || kept[j] != (near ? 1 : 0);
                    neighbours += near;
                }
                ++checked;
            }
        }
        CHECK(checked == set.size());
        CHECK(wrong == 0);
        CHECK(neighbours > 10 * set.size());
    });
}

TEST_CASE("each pair once: a particle keeps exactly its neighbours whose key is above its own, on every path")
{
    on_every_path(41, [](const ParticleSet& set, int dim, bool periodic) {
        const double reach = dim == 3 ? 0.18 : 0.12;
        const NeighbourGrid grid(set, reach);
        const PairOrder order(grid);
        const std::vector<double> ids = point_indices(grid);
        ClusterCandidates cluster;
        Neighbours nb;
        std::size_t wrong = 0, taken = 0, ghosts = 0;
        for (std::size_t c = 0; c < grid.clusters(); ++c) {
            gather_cluster(grid, c, {nullptr, reach}, ids.data(), nullptr, cluster, &order);
            for (std::size_t p = grid.cluster_begin(c); p < grid.cluster_end(c); ++p) {
                if (!grid.visited(p)) continue;
                gather_from_cluster(grid, cluster, p, reach * reach, set.name, nb);
                std::vector<int> kept(grid.points(), 0);
                for (std::size_t j = 0; j < nb.count; ++j) {
                    const auto point = static_cast<std::size_t>(nb.a[j]);
                    kept[point] += 1;
                    // The slot names the neighbour's place among the cluster's candidates.
                    wrong += cluster.key[static_cast<std::size_t>(nb.slot[j])] != order.keys[point];
                }
                for (std::size_t j = 0; j < grid.points(); ++j) {
                    const bool near = within(grid, j, p, reach);
                    const bool later = grid.visited(j) ? j > p : true;
                    wrong += kept[j] != (near && later ? 1 : 0);
                    taken += near && later && grid.visited(j), ghosts += near && !grid.visited(j);
                }
            }
        }
        CHECK(wrong == 0);
        // Every pair of particles within reach, by brute force over the set (and its
        // images in a periodic box), taken once; a pair through a ghost from both sides.
        std::size_t pairs = 0, across = 0;
        for (std::size_t i = 0; i < set.size(); ++i)
            for (std::size_t j = i + 1; j < set.size(); ++j) {
                Eigen::Vector3d d = set.position(j) - set.position(i);
                bool wrapped = false;
                for (int axis = 0; periodic && axis < dim; ++axis) { // the nearest image (a rectangular box)
                    const double side = set.box->edges(axis, axis), shift = side * std::round(d[axis] / side);
                    d[axis] -= shift, wrapped = wrapped || shift != 0;
                }
                if (d.norm() > reach) continue;
                pairs += !wrapped, across += wrapped;
            }
        CHECK(taken == pairs);
        CHECK(ghosts == 2 * across);
        CHECK(pairs > 5 * set.size());
    });
}

namespace {

// Per particle (the set's order): sum_j w(r / R) and sum_j w'(r / R) (x_j - x_i) / r over the
// neighbours within R, with w(q) = (1 - q^2)^3, once by every particle gathering its own and
// once by the pass that takes each pair once (on `threads` threads).
struct PairSumsBothWays {
    std::vector<double> gathered, paired; // four a particle
};
PairSumsBothWays pair_sums_both_ways(const ParticleSet& set, double reach, int threads)
{
    const NeighbourGrid grid(set, reach, threads);
    auto terms = [&](const Neighbours& nb, std::size_t j, double* t) {
        const double r = std::sqrt(nb.r2[j]), q = r / reach, u = 1 - q * q, slope = -6 * q * u * u / r;
        t[0] = u * u * u, t[1] = slope * nb.dx[j], t[2] = slope * nb.dy[j], t[3] = slope * nb.dz[j];
    };
    PairSumsBothWays out{std::vector<double>(4 * set.size()), std::vector<double>(4 * set.size())};
    pair_pass(
        grid, set.name, {{nullptr, reach}, nullptr, nullptr, true, ""}, threads,
        [&](int, std::size_t p, Neighbours& nb) {
            double* own = out.gathered.data() + 4 * grid.source(p);
            for (std::size_t j = 0; j < nb.count; ++j) {
                double t[4];
                terms(nb, j, t);
                for (int a = 0; a < 4; ++a) own[a] += t[a];
            }
        },
        [](int) {});
    std::vector<double> sums(4 * (grid.points() + 1));
    symmetric_pair_pass<4>(
        grid, set.name, {reach, nullptr, nullptr, true, ""}, threads, sums.data(),
        [&](std::size_t p, Neighbours& nb, double* cluster_sums) {
            std::vector<double> theirs[4]; // per call: each thread its own
            for (auto& v : theirs) v.assign(nb.count, 0.0);
            for (std::size_t j = 0; j < nb.count; ++j) {
                double t[4];
                terms(nb, j, t);
                for (int a = 0; a < 4; ++a) sums[4 * p + a] += t[a];
                // The other particle's: the same value, the opposite gradient.
                theirs[0][j] = t[0], theirs[1][j] = -t[1], theirs[2][j] = -t[2], theirs[3][j] = -t[3];
            }
            add_to_pairs<4>(nb, {theirs[0].data(), theirs[1].data(), theirs[2].data(), theirs[3].data()}, cluster_sums);
        });
    for_each_visited(grid, threads, [&](std::size_t p, std::size_t i) {
        for (int a = 0; a < 4; ++a) out.paired[4 * i + a] = sums[4 * p + a];
    });
    return out;
}

} // namespace

TEST_CASE("each pair once equals every particle gathering its own (1e-13) on lattice, Poisson and file sets, 2D and "
          "3D, with neighbours-only particles, and is the same bits on 1, 2 and 7 threads")
{
    const auto dir = std::filesystem::temp_directory_path() / ("sphkern-pairs-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    std::vector<test::PairTestSet> cases = test::pair_test_sets(7);
    LatticeBlockSpec spec;
    spec.sigma = 0.05, spec.cells = {14, 12, 1};
    cases.push_back({"triangular block", lattice_particles(load_lattice("triangular"), spec), 2.3});
    {
        // A file: positions as a CSV holds them, in two clumps of different density, with no box.
        ParticleSet clumps = random_set(3, 4000, false, 5);
        for (std::size_t i = 0; i < clumps.size(); i += 2) clumps.x[i] *= 0.3, clumps.y[i] *= 0.3;
        std::ofstream csv(dir / "clumps.csv");
        csv << "x,y,z\n" << std::setprecision(17);
        for (std::size_t i = 0; i < clumps.size(); ++i)
            csv << clumps.x[i] << ',' << clumps.y[i] << ',' << clumps.z[i] << '\n';
    }
    cases.push_back({"CSV file", read_particle_file(dir / "clumps.csv", {}), 0.12});
    ParticleSet some_neighbours_only = random_set(3, 5000, true, 3);
    some_neighbours_only.neighbours_only = 1500; // the last 1500: candidates only
    cases.push_back({"Poisson with neighbours-only particles", some_neighbours_only, 0.13});
    for (const test::PairTestSet& c : cases) {
        CAPTURE(c.name);
        const auto one = pair_sums_both_ways(c.set, c.reach, 1);
        double worst = 0, scale = 0;
        for (std::size_t i = 0; i < 4 * c.set.measured(); ++i)
            worst = std::max(worst, std::abs(one.paired[i] - one.gathered[i])),
            scale = std::max(scale, std::abs(one.gathered[i]));
        CHECK(scale > 1);
        CHECK(worst < 1e-13 * scale);
        for (int threads : {2, 7}) CHECK(pair_sums_both_ways(c.set, c.reach, threads).paired == one.paired);
    }
    std::filesystem::remove_all(dir);
}

TEST_CASE("a long thin set gets no more bins than four per point, and every neighbour is still found")
{
    // A diagonal line of points, 2000 reaches long: the per-axis bin counts alone would multiply
    // to about 2000^3 / 16 bins.
    ParticleSet set;
    set.name = "line";
    set.dimension = 3;
    const double reach = 1.0;
    for (int i = 0; i < 4000; ++i) {
        const double t = 0.5 * i;
        set.x.push_back(t), set.y.push_back(t + 0.1 * (i % 3)), set.z.push_back(t + 0.1 * (i % 5));
    }
    const NeighbourGrid grid(set, reach);
    CHECK(static_cast<double>(grid.bins()) <= 4.0 * static_cast<double>(grid.points()) + 64);
    std::vector<double> reaches(grid.points(), reach);
    ClusterCandidates cluster;
    Neighbours nb;
    std::size_t found = 0, expected = 0;
    for (std::size_t c = 0; c < grid.clusters(); ++c) {
        gather_cluster(grid, c, {reaches.data(), 0}, nullptr, nullptr, cluster);
        for (std::size_t p = grid.cluster_begin(c); p < grid.cluster_end(c); ++p) {
            gather_from_cluster(grid, cluster, p, reach * reach, set.name, nb);
            found += nb.count;
        }
    }
    for (std::size_t i = 0; i < set.size(); ++i)
        for (std::size_t j = 0; j < set.size(); ++j) {
            const double dx = set.x[j] - set.x[i], dy = set.y[j] - set.y[i], dz = set.z[j] - set.z[i];
            expected += j != i && dx * dx + dy * dy + dz * dz <= reach * reach;
        }
    CHECK(expected > set.size());
    CHECK(found == expected);
}

TEST_CASE("copies of a periodic set side by side: each copy where its shift puts it, and every particle's sums as in "
          "the original")
{
    const auto kernel = shipped_kernel("cubic_bspline");
    for (const int dim : {2, 3}) {
        CAPTURE(dim);
        PoissonSpec spec;
        spec.dimension = dim;
        spec.count = dim == 2 ? 900 : 2000;
        spec.box = Eigen::Vector3d(1.5, 1.0, 0.75);
        auto set = poisson_particles(spec);
        set.mass.assign(set.size(), 0.5);
        const std::array<int, 3> tiles = dim == 2 ? std::array<int, 3>{3, 2, 1} : std::array<int, 3>{2, 1, 3};
        const auto big = tiled_set(set, tiles, 3);
        const std::size_t n = set.size(), copies = static_cast<std::size_t>(tiles[0] * tiles[1] * tiles[2]);
        REQUIRE(big.size() == copies * n);
        for (int a = 0; a < dim; ++a)
            CHECK(big.box->edges(a, a) == set.box->edges(a, a) * tiles[static_cast<std::size_t>(a)]);
        // Copy (i0, i1, i2) holds the original moved by i0 edges along x, i1 along y, i2 along z.
        std::size_t c = 0;
        for (int i2 = 0; i2 < (dim == 3 ? tiles[2] : 1); ++i2)
            for (int i1 = 0; i1 < tiles[1]; ++i1)
                for (int i0 = 0; i0 < tiles[0]; ++i0, ++c)
                    for (std::size_t i = 0; i < n; i += 97) {
                        const std::size_t k = c * n + i;
                        CHECK(big.x[k] == set.x[i] + i0 * spec.box.x());
                        CHECK(big.y[k] == set.y[i] + i1 * spec.box.y());
                        CHECK(big.z[k] == (dim == 3 ? set.z[i] + i2 * spec.box.z() : 0.0));
                        CHECK(big.mass[k] == 0.5);
                    }
        // Periodic images are the copies: every copy of a particle has its sums (to rounding).
        ParticleRequest request;
        request.smoothing = {SmoothingRule::nh, dim == 2 ? 20.0 : 50.0, 0};
        request.volume = VolumeModel::uniform;
        const auto one = analyse_particles(kernel, set, request);
        const auto all = analyse_particles(kernel, big, request);
        double worst = 0;
        for (std::size_t k = 0; k < big.size(); ++k) {
            worst = std::max(worst, std::abs(all.measures->scalars[k].e0 - one.measures->scalars[k % n].e0));
            CHECK(all.measures->scalars[k].neighbours == one.measures->scalars[k % n].neighbours);
        }
        CHECK(worst < 1e-12);
    }
    ParticleSet open;
    open.x = open.y = open.z = ParticleValues(4, 0.0);
    CHECK_THROWS_AS(tiled_set(open, {2, 2, 2}), Error);
}

TEST_CASE(
    "a rectangular cell holds the lattice's own points, and a block cut from it has the lattice's sums at every site")
{
    const auto kernel = shipped_kernel("cubic_bspline");
    for (const std::string name : {"triangular", "square", "fcc", "bcc", "hcp", "sc", "hex_prism"}) {
        CAPTURE(name);
        const auto lattice = load_lattice(name);
        const auto cell = rectangular_cell(lattice);
        const int dim = lattice.dimension;
        REQUIRE(cell.motif.size() % lattice.motif.size() == 0);
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
                if (a != b) CHECK(cell.basis(a, b) == 0);
        // As many sites as the rectangle holds primitive cells, each a point of the lattice: the
        // primitive site it is, by its fractional coordinates.
        const double cells = std::abs(cell.basis.topLeftCorner(dim, dim).determinant() /
                                      lattice.basis.topLeftCorner(dim, dim).determinant());
        CHECK(static_cast<double>(cell.motif.size()) ==
              doctest::Approx(cells * static_cast<double>(lattice.motif.size())));
        std::vector<std::size_t> primitive_site;
        for (const auto& s : cell.motif) {
            const Eigen::Vector3d f = lattice.basis.inverse() * (cell.basis * s);
            std::size_t found = lattice.motif.size();
            for (std::size_t j = 0; j < lattice.motif.size(); ++j) {
                const Eigen::Vector3d n = f - lattice.motif[j];
                bool whole = true;
                for (int a = 0; a < dim; ++a) whole = whole && std::abs(n[a] - std::round(n[a])) < 1e-9;
                if (whole) found = j;
            }
            REQUIRE(found < lattice.motif.size());
            primitive_site.push_back(found);
        }
        // Every particle of the rectangular block has the sums of its site on the lattice.
        const double k = 1.13;
        LatticeBlockSpec spec;
        spec.cells = dim == 2 ? std::array<long long, 3>{8, 5, 1} : std::array<long long, 3>{6, 5, 5};
        spec.rectangular = true;
        const auto set = lattice_particles(block_cell(lattice, spec), spec);
        for (int a = 0; a < dim; ++a)
            CHECK(set.box->edges(a, a) ==
                  cell.basis(a, a) * static_cast<double>(spec.cells[static_cast<std::size_t>(a)]));
        ParticleRequest request;
        request.smoothing = {SmoothingRule::k, k, 0};
        const auto answer = analyse_particles(kernel, set, request);
        const auto sites = errors_per_site(kernel, lattice, every_site(lattice), lattice.volume_coefficient("voronoi"),
                                           lattice.gravity, k);
        double worst = 0;
        for (std::size_t i = 0; i < set.size(); ++i) {
            const auto values = sites[primitive_site[i % cell.motif.size()]]->at(k);
            worst = std::max(worst, std::abs(answer.measures->scalars[i].e0 - values.eps_rho));
            REQUIRE(answer.measures->scalars[i].neighbours == values.neighbours);
        }
        CHECK(worst < 1e-12);
    }
}
