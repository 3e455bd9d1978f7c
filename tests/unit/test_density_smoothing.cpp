// h from the SPH density (particles --code swift, phantom, gadget): every particle's h
// against its definition, h_i = c (m_i / rho_i)^(1/D), with rho_i summed here pair by pair
// over the periodic images, and on a lattice block against the lattice's own solution.
#include "helpers.hpp"
#include "pair_test_sets.hpp"
#include "particles/density_smoothing.hpp"
#include "particles/particle_measures.hpp"
#include "particles/sources/lattice_particles.hpp"
#include "particles/sources/poisson_particles.hpp"
#include "requests/code_setting.hpp"
#include "requests/eps_request.hpp"

#include <doctest/doctest.h>

#include <boost/random/mersenne_twister.hpp>
#include <boost/random/uniform_real_distribution.hpp>

#include <cmath>
#include <optional>

using namespace sphkern;
using namespace sphkern::test;

namespace {

// sum_j w_j W(|r_ij|, h) over every periodic image, the particle itself included; w_j = 1 without weights.
double brute_sum(const Kernel& kernel, const ParticleSet& set, std::size_t i, double h, const ParticleValues* weights)
{
    const Eigen::Matrix3d& edges = set.box->edges;
    double sum = 0;
    for (std::size_t j = 0; j < set.size(); ++j)
        for (int a = -1; a <= 1; ++a)
            for (int b = -1; b <= 1; ++b)
                for (int c = -1; c <= 1; ++c) {
                    const Eigen::Vector3d r =
                        Eigen::Vector3d(set.x[j] - set.x[i], set.y[j] - set.y[i], set.z[j] - set.z[i]) +
                        edges * Eigen::Vector3d(a, b, c);
                    sum += (weights ? (*weights)[j] : 1.0) * kernel.w_truncated(r.norm() / h, 3, h) / (h * h * h);
                }
    return sum;
}

// rho_i = sum_j m W(|r_ij|, h_i) over every periodic image, the particle itself included.
double brute_density(const Kernel& kernel, const ParticleSet& set, std::size_t i, double h, double m)
{
    return m * brute_sum(kernel, set, i, h, nullptr);
}

} // namespace

TEST_CASE("h from the SPH density holds its definition for every particle of a Poisson set")
{
    const auto kernel = shipped_kernel("wendland_c2");
    const ParticleSet set = poisson_particles({3, 400, Eigen::Vector3d::Ones(), 7});
    const double volume = 1.0 / 400, c = 1.4;
    const auto h = density_smoothing_lengths(kernel, set, c, volume, 2);
    REQUIRE(h.size() == set.size());
    for (std::size_t i = 0; i < set.size(); i += 7) {
        CAPTURE(i);
        const double rho = brute_density(kernel, set, i, h[i], volume);
        CHECK(h[i] == doctest::Approx(c * std::cbrt(volume / rho)).epsilon(1e-10));
    }
}

TEST_CASE("h from the SPH density where h spans a factor 1.7: its definition, and the same bits on 1, 2 and 3 threads")
{
    // Half the particles squeezed into a sixth of the box: densities 5 to 1, h 1.7 to 1, so the
    // mean density's first guess is off by more than a pass's margin for thousands of particles, which
    // a second pass solves with neighbour lists of its own.
    const auto kernel = shipped_kernel("wendland_c2");
    ParticleSet set = poisson_particles({3, 12000, Eigen::Vector3d::Ones(), 5}); // 3 grid threads from 8192 on
    for (std::size_t i = 0; i < set.size(); ++i)
        set.x[i] = set.x[i] < 0.5 ? set.x[i] / 3 : 1.0 / 6 + (set.x[i] - 0.5) * 5 / 3;
    const double volume = 1.0 / 12000, c = 1.4;
    const auto h = density_smoothing_lengths(kernel, set, c, volume, 1);
    double smallest = INFINITY, largest = 0;
    for (std::size_t i = 0; i < set.size(); ++i) smallest = std::min(smallest, h[i]), largest = std::max(largest, h[i]);
    CHECK(largest / smallest > 1.5);
    for (std::size_t i = 0; i < set.size(); i += 101) {
        CAPTURE(i);
        const double rho = brute_density(kernel, set, i, h[i], volume);
        CHECK(h[i] == doctest::Approx(c * std::cbrt(volume / rho)).epsilon(1e-10));
    }
    for (int threads : {2, 3}) {
        CAPTURE(threads);
        const auto again = density_smoothing_lengths(kernel, set, c, volume, threads);
        std::size_t differ = 0;
        for (std::size_t i = 0; i < set.size(); ++i) differ += again[i] != h[i];
        CHECK(differ == 0);
    }
}

TEST_CASE("SWIFT's eta on an fcc block gives every particle the k that eps --code finds on the lattice")
{
    const auto kernel = shipped_kernel("wendland_c2");
    const auto lattice = load_lattice("fcc");
    const CodeSetting swift{"swift", 1.2348};
    const CodeSettingSources sources{ValueSource::option("--code"), ValueSource::option("--eta")};
    const auto spec = code_smoothing(swift, sources, kernel, 3);
    CHECK(spec.rule == SmoothingRule::density);
    // A periodic block of 6 x 6 x 6 primitive cells: every particle sees the lattice's sums.
    const ParticleSet block = lattice_particles(lattice, {{6, 6, 6}, 0, 1, false});
    const double volume = lattice.volume_coefficient("voronoi");
    const auto h = density_smoothing_lengths(kernel, block, spec.value, volume, 2);
    EpsRequest request;
    request.code = swift;
    const EvaluationSources evaluation{ValueSource::option("--gravity"), ValueSource::option("--site"),
                                       ValueSource::option("--shells")};
    const EpsSources eps{ValueSource::option("--k"), ValueSource::option("--axis"), evaluation, sources.code,
                         sources.value};
    const double k = run_eps_at_k(request, eps, kernel, lattice).k;
    for (std::size_t i = 0; i < block.size(); i += 17) CHECK(h[i] == doctest::Approx(k).epsilon(1e-9));
    // PySPH and DualSPHysics set h from the spacing: one h for all, no density solved.
    CHECK(code_smoothing({"pysph", 1.2}, sources, kernel, 3).rule == SmoothingRule::eta);
}

namespace {

// Particle i's h by its code's own rule, bisected here on [h0 / 4, 4 h0]: by mass
// h = c (m_i / sum_j m_j W_ij)^(1/3) (Phantom's rhoh in part.F90; GADGET-4's NumNgb from the
// density in density.cc), by number h = c (1 / sum_j W_ij)^(1/3) (SWIFT's wcount in
// runner_do_ghost; GADGET-2's weighted_numngb in density.c: no masses).
double rule_h(const Kernel& kernel, const ParticleSet& set, std::size_t i, double c, bool by_number, double h0)
{
    auto g = [&](double h) {
        const double per = by_number ? 1 / brute_sum(kernel, set, i, h, nullptr)
                                     : set.mass[i] / brute_sum(kernel, set, i, h, &set.mass);
        return h - c * std::cbrt(per);
    };
    double lo = h0 / 4, hi = 4 * h0;
    REQUIRE(g(lo) < 0);
    REQUIRE(g(hi) > 0);
    for (int step = 0; step < 80; ++step) (g(0.5 * (lo + hi)) < 0 ? lo : hi) = 0.5 * (lo + hi);
    return 0.5 * (lo + hi);
}

} // namespace

TEST_CASE(
    "each code counts its neighbours as its source does: SWIFT and GADGET-2 by number, Phantom and GADGET-4 by mass")
{
    const auto kernel = shipped_kernel("cubic_bspline");
    ParticleSet set = poisson_particles({3, 600, Eigen::Vector3d::Ones(), 11});
    const double volume = 1.0 / 600;
    // Masses over a factor 4, as in SWIFT's SquareTest.
    set.mass.resize(set.size());
    for (std::size_t i = 0; i < set.size(); ++i) set.mass[i] = volume * (i % 3 == 0 ? 4.0 : 1.0);
    const CodeSettingSources sources{ValueSource::option("--code"), ValueSource::option("--eta")};
    struct Rule {
        CodeSetting setting;
        bool by_number;
    };
    const Rule rules[] = {{{"swift", 1.2348}, true},
                          {{"gadget2", 48}, true},
                          {{"phantom", 1.2}, false},
                          {{"gadget4", 48}, false}};
    for (const auto& [setting, number] : rules) {
        CAPTURE(setting.code);
        const auto spec = code_smoothing(setting, sources, kernel, 3);
        REQUIRE(spec.rule == SmoothingRule::density);
        CHECK(spec.by_number == number);
        const auto h = density_smoothing_lengths(kernel, set, spec.value, volume, 2, spec.by_number);
        for (std::size_t i = 0; i < set.size(); i += 26) {
            CAPTURE(i);
            CHECK(h[i] == doctest::Approx(rule_h(kernel, set, i, spec.value, number, spec.value * std::cbrt(volume)))
                              .epsilon(1e-9));
        }
        // Where masses differ by 4, the other rule's h is off by more than 10% for some particle.
        double largest = 0;
        for (std::size_t i = 0; i < set.size(); i += 53)
            largest = std::max(largest, std::abs(rule_h(kernel, set, i, spec.value, !number, h[i]) / h[i] - 1));
        CHECK(largest > 0.1);
    }
}

namespace {

// |a - b| within 1e-13 of the larger of 1 and |a|.
bool near(double a, double b) { return std::abs(a - b) <= 1e-13 * std::max(1.0, std::abs(a)); }

// The particles whose measures differ from `expected`'s beyond near(), or in their neighbour count.
std::size_t measures_differ(const ParticleMeasures& got, const ParticleMeasures& expected)
{
    std::size_t differ = 0;
    for (std::size_t i = 0; i < expected.size(); ++i) {
        const MeasureRecord &a = got.scalars[i], &b = expected.scalars[i];
        bool same = a.neighbours == b.neighbours && near(a.e0, b.e0) && near(a.eps_gradp, b.eps_gradp) &&
                    near(a.eps_gradp_sum, b.eps_gradp_sum) && near(a.e1_norm, b.e1_norm) &&
                    near(a.m1_norm, b.m1_norm) && near(a.E_norm, b.E_norm) && near(a.lambda_min, b.lambda_min) &&
                    near(got.eps_rho_of(i), expected.eps_rho_of(i));
        for (std::size_t c = 0; c < 6; ++c) same = same && near(got.E[i][c], expected.E[i][c]);
        for (std::size_t c = 0; c < 3; ++c) same = same && near(got.e1[i][c], expected.e1[i][c]);
        differ += !same;
    }
    return differ;
}

bool same_bits(const ParticleMeasures& a, const ParticleMeasures& b)
{
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a.scalars[i].e0 != b.scalars[i].e0 || a.scalars[i].eps_gradp != b.scalars[i].eps_gradp ||
            a.eps_rho_of(i) != b.eps_rho_of(i) || a.E[i] != b.E[i] || a.e1[i] != b.e1[i] || a.m1[i] != b.m1[i])
            return false;
    return a.pairs == b.pairs;
}

} // namespace

TEST_CASE("the measures taken inside the density solve are a separate pass's at its h, the same bits on any threads")
{
    // Poisson sets in 2D and 3D, periodic and free, and a disturbed fcc block; masses and
    // volumes differing per particle (the set's masses are the solve's), or the volumes uniform.
    const auto kernel = shipped_kernel("wendland_c2");
    std::uint64_t seed = 3;
    for (auto& [name, set, unused] : pair_test_sets(17))
        for (bool volumes_differ : {true, false}) {
            CAPTURE(name);
            CAPTURE(volumes_differ);
            const double mean_volume = set.box ? set.box->volume(set.dimension) / static_cast<double>(set.size())
                                               : (set.dimension == 3 ? 1.17 : 1.3) / static_cast<double>(set.size());
            boost::random::mt19937_64 engine(seed++);
            boost::random::uniform_real_distribution<double> u(0.8, 1.25);
            std::vector<double> volume(set.size());
            set.mass.resize(set.size());
            for (std::size_t i = 0; i < set.size(); ++i)
                volume[i] = mean_volume * u(engine), set.mass[i] = mean_volume * u(engine);
            MeasureInputs in;
            in.volume = volumes_differ ? PerParticleView::of(volume) : PerParticleView{{}, mean_volume, set.size()};
            in.mass = set.mass, in.spacing = std::pow(mean_volume, 1.0 / set.dimension);
            const double c = name == "fcc block" ? 1.05 : 1.3; // the block's box is 4.9 d wide
            const PerParticle h = density_smoothing_lengths(kernel, set, c, mean_volume, 2);
            in.h = h.view();
            const ParticleMeasures separate = measure_particles(kernel, set, in);
            std::optional<ParticleMeasures> first;
            for (int threads : {1, 2, 3}) {
                CAPTURE(threads);
                MeasureCollector collector(kernel, set, in, threads);
                const PerParticle solved =
                    density_smoothing_lengths(kernel, set, c, mean_volume, threads, false, 1, &collector);
                ParticleMeasures fused = collector.finish();
                std::size_t h_differ = 0;
                for (std::size_t i = 0; i < set.size(); ++i) h_differ += solved[i] != h[i];
                CHECK(h_differ == 0); // the solve is the same with its measures
                CHECK(fused.pairs == separate.pairs);
                CHECK(measures_differ(fused, separate) == 0);
                if (first) CHECK(same_bits(fused, *first));
                else first.emplace(std::move(fused));
            }
        }
}
