// h from the SPH density (particles --code swift, phantom, gadget): every particle's h
// against its definition, h_i = c (m_i / rho_i)^(1/D), with rho_i summed here pair by pair
// over the periodic images, and on a lattice block against the lattice's own solution.
#include "helpers.hpp"
#include "particles/density_smoothing.hpp"
#include "particles/sources/lattice_particles.hpp"
#include "particles/sources/poisson_particles.hpp"
#include "requests/code_setting.hpp"
#include "requests/eps_request.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace sphkern;
using namespace sphkern::test;

namespace {

// rho_i = sum_j m W(|r_ij|, h_i) over every periodic image, the particle itself included.
double brute_density(const Kernel& kernel, const ParticleSet& set, std::size_t i, double h, double m)
{
    const Eigen::Matrix3d& edges = set.box->edges; // columns: the box's edge vectors
    double sum = 0;
    for (std::size_t j = 0; j < set.size(); ++j)
        for (int a = -1; a <= 1; ++a)
            for (int b = -1; b <= 1; ++b)
                for (int c = -1; c <= 1; ++c) {
                    const Eigen::Vector3d r = Eigen::Vector3d(set.x[j] - set.x[i], set.y[j] - set.y[i], set.z[j] - set.z[i]) +
                                              edges * Eigen::Vector3d(a, b, c);
                    sum += kernel.w_truncated(r.norm() / h, 3, h) / (h * h * h);
                }
    return m * sum;
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
    const EpsSources eps{ValueSource::option("--k"), ValueSource::option("--axis"), evaluation, sources.code, sources.value};
    const double k = run_eps_at_k(request, eps, kernel, lattice).k;
    for (std::size_t i = 0; i < block.size(); i += 17) CHECK(h[i] == doctest::Approx(k).epsilon(1e-9));
    // PySPH and DualSPHysics set h from the spacing: one h for all, no density solved.
    CHECK(code_smoothing({"pysph", 1.2}, sources, kernel, 3).rule == SmoothingRule::eta);
}
