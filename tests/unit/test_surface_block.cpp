// Free-surface profiles against an independent half-space brute-force sum, and the
// particle block against the bulk shell sums and the surface profiles.
#include "analysis/surface_profile.hpp"
#include "block/particle_block.hpp"
#include "helpers.hpp"
#include "support/error.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace sphkern;
using sphkern::test::shipped_kernel;

namespace {

struct LayerValue {
    double eps_rho, eps_gradp;
};

// Layer n of a half-space below a free surface normal to e, summed point by point
// over a large box: densities first (needed by the Monaghan form), then the gradient.
LayerValue brute_force_layer(const Kernel& kernel, const Lattice& lattice, double k, double a_p,
                             const Eigen::Vector3d& e, double spacing, int n, GradientForm form)
{
    const int dim = lattice.dimension, box = 10;
    const double R = kernel.support(), kd = std::pow(k, dim);
    std::vector<Eigen::Vector3d> points;
    for (int a = -box; a <= box; ++a)
        for (int b = -box; b <= box; ++b)
            for (int c = (dim == 3 ? -box : 0); c <= (dim == 3 ? box : 0); ++c)
                for (const auto& m : lattice.motif)
                    points.push_back(lattice.basis * (Eigen::Vector3d(a, b, c) + m - lattice.motif[0]));
    // Density of a particle at depth m * spacing (its neighbours: depth >= 0).
    auto density = [&](int m) {
        double sum = 0;
        for (const auto& x : points) {
            double r = x.norm();
            if (r / k <= R && m * spacing + e.dot(x) > -1e-9) sum += kernel.w(r / k, dim, k);
        }
        return a_p * sum / kd;
    };
    const double depth_i = n * spacing, rho_i = density(n);
    double gradient = 0;
    for (const auto& x : points) {
        double r = x.norm();
        double depth_j = depth_i + e.dot(x);
        if (r < 1e-12 || r / k > R || depth_j < -1e-9) continue;
        double weight = form == GradientForm::sum          ? depth_i + depth_j
                        : form == GradientForm::difference ? depth_j - depth_i
                                                           : rho_i * (depth_i / (rho_i * rho_i) +
                                                                      depth_j / std::pow(density(static_cast<int>(std::lround(depth_j / spacing))), 2));
        gradient += weight * kernel.dw(r / k, dim, k) * (-e.dot(x)) / r;
    }
    return {rho_i - 1, a_p * gradient / (kd * k) - 1};
}

} // namespace

TEST_CASE("surface profiles equal a half-space brute-force sum, every form, 2D and 3D")
{
    for (const char* lattice_name : {"triangular", "square", "fcc", "hcp"})
        for (const char* kernel_name : {"cubic_bspline", "wendland_c2"})
            for (auto form : {GradientForm::sum, GradientForm::difference, GradientForm::monaghan}) {
                auto lattice = load_lattice(lattice_name);
                Kernel kernel = shipped_kernel(kernel_name);
                double a_p = lattice.volume_coefficient("voronoi"), k = 1.15;
                auto profile = surface_profile(kernel, lattice, 0, a_p, lattice.gravity, k, 3, form);
                CAPTURE(lattice_name);
                CAPTURE(kernel_name);
                CAPTURE(gradient_form_name(form));
                for (int n = 0; n < 4; ++n) {
                    auto expected = brute_force_layer(kernel, lattice, k, a_p, lattice.gravity, profile.spacing, n, form);
                    CHECK(profile.layers[static_cast<std::size_t>(n)].eps_rho == doctest::Approx(expected.eps_rho).epsilon(1e-12));
                    CHECK(profile.layers[static_cast<std::size_t>(n)].eps_gradp == doctest::Approx(expected.eps_gradp).epsilon(1e-12));
                }
                // The deepest layers reported are the bulk of method.md section 2; Monaghan's
                // form divides by the SPH density there: (1 + eps_gradP) / (1 + eps_rho) - 1.
                auto b = HydrostaticErrors(kernel, lattice, 0, a_p, lattice.gravity, k).at(k);
                double gradp = form == GradientForm::monaghan ? (1 + b.eps_gradp) / (1 + b.eps_rho) - 1 : b.eps_gradp;
                CHECK(profile.layers.back().eps_rho == doctest::Approx(b.eps_rho).epsilon(1e-12));
                CHECK(profile.layers.back().eps_gradp == doctest::Approx(gradp).epsilon(1e-12));
                CHECK(profile.bulk.eps_gradp == doctest::Approx(gradp).epsilon(1e-12));
            }
}

TEST_CASE("every shipped lattice has a surface profile along its default gravity that ends in the bulk")
{
    for (const auto& name : shipped_lattice_names()) {
        auto lattice = load_lattice(name);
        Kernel kernel = shipped_kernel("wendland_c2");
        double a_p = lattice.volume_coefficient("voronoi");
        auto profile = surface_profile(kernel, lattice, 0, a_p, lattice.gravity, 1.2, 2, GradientForm::difference);
        auto bulk = HydrostaticErrors(kernel, lattice, 0, a_p, lattice.gravity, 1.2).at(1.2);
        CAPTURE(name);
        CHECK(profile.layers.back().eps_rho == doctest::Approx(bulk.eps_rho).epsilon(1e-12));
        CHECK(profile.layers.back().eps_gradp == doctest::Approx(bulk.eps_gradp).epsilon(1e-12));
        CHECK(profile.layers.front().neighbours < bulk.neighbours);
    }
}

TEST_CASE("a gravity direction not normal to a lattice plane is refused")
{
    auto lattice = load_lattice("triangular");
    Kernel kernel = shipped_kernel("cubic_bspline");
    Eigen::Vector3d tilted(std::sqrt(2.0), -1, 0);
    CHECK_THROWS_WITH_AS(surface_profile(kernel, lattice, 0, 1.0, tilted.normalized(), 1.2, 3, GradientForm::sum),
                         doctest::Contains("not normal to a family of equally spaced planes"), Error);
    // Along a lattice row is fine: the planes normal to x.
    CHECK_NOTHROW(surface_profile(kernel, lattice, 0, 1.0, Eigen::Vector3d(-1, 0, 0), 1.2, 3, GradientForm::sum));
}

TEST_CASE("block: interior particles equal the bulk shell sums, top layers the surface profile")
{
    struct Case {
        const char* lattice;
        std::array<long long, 3> cells;
    };
    for (const auto& c : {Case{"triangular", {16, 24, 1}}, Case{"fcc", {8, 8, 20}}, Case{"hcp", {8, 8, 11}},
                          Case{"bcc", {8, 8, 14}}})
        for (auto form : {GradientForm::sum, GradientForm::difference, GradientForm::monaghan}) {
            auto lattice = load_lattice(c.lattice);
            Kernel kernel = shipped_kernel("cubic_bspline");
            BlockOptions options;
            options.cells = c.cells;
            options.periodic = true;
            options.k = 1.2;
            options.a_p = lattice.volume_coefficient("voronoi");
            options.form = form;
            auto block = evaluate_block(kernel, lattice, options);
            auto profile = surface_profile(kernel, lattice, 0, options.a_p, block.gravity, options.k, 1, form);
            auto expected_bulk = HydrostaticErrors(kernel, lattice, 0, options.a_p, block.gravity, options.k).at(options.k);
            CAPTURE(c.lattice);
            CAPTURE(gradient_form_name(form));
            const int deepest = *std::max_element(block.layer.begin(), block.layer.end());
            const int settled = static_cast<int>(profile.layers.size());
            int compared_top = 0, compared_bulk = 0;
            for (std::size_t i = 0; i < block.layer.size(); ++i) {
                int n = block.layer[i];
                if (deepest - n < settled + 2) continue; // near the free bottom
                if (n < settled) {
                    const auto& l = profile.layers[static_cast<std::size_t>(n)];
                    CHECK(std::abs(block.eps_rho[i] - l.eps_rho) <= 1e-12 * (1 + std::abs(l.eps_rho)));
                    CHECK(std::abs(block.eps_gradp[i] - l.eps_gradp) <= 1e-12 * (1 + std::abs(l.eps_gradp)));
                    ++compared_top;
                } else {
                    CHECK(std::abs(block.eps_rho[i] - expected_bulk.eps_rho) <= 1e-12);
                    CHECK(std::abs(block.eps_gradp[i] - profile.bulk.eps_gradp) <= 1e-12 * (1 + n));
                    ++compared_bulk;
                }
            }
            CHECK(compared_top > 0);
            CHECK(compared_bulk > 0);
        }
}

TEST_CASE("block results do not depend on the thread count")
{
    auto lattice = load_lattice("fcc");
    Kernel kernel = shipped_kernel("wendland_c4");
    BlockOptions options;
    options.cells = {9, 8, 7};
    options.periodic = true;
    options.k = 1.1;
    options.form = GradientForm::monaghan;
    options.threads = 1;
    auto one = evaluate_block(kernel, lattice, options);
    for (int threads : {2, 3, 7}) {
        options.threads = threads;
        auto many = evaluate_block(kernel, lattice, options);
        CHECK(many.eps_rho == one.eps_rho);
        CHECK(many.eps_gradp == one.eps_gradp);
        CHECK(many.pair_interactions == one.pair_interactions);
    }
}

TEST_CASE("block sizes are checked before anything is allocated")
{
    auto lattice = load_lattice("fcc");
    Kernel kernel = shipped_kernel("cubic_bspline");
    BlockOptions options;
    options.k = 1.2;
    options.cells = {0, 10, 10};
    CHECK_THROWS_WITH_AS(evaluate_block(kernel, lattice, options), doctest::Contains("positive number of cells"), Error);
    options.cells = {-3, 10, 10};
    CHECK_THROWS_WITH_AS(evaluate_block(kernel, lattice, options), doctest::Contains("positive number of cells"), Error);
    options.cells = {100000, 100000, 100000};
    CHECK_THROWS_WITH_AS(evaluate_block(kernel, lattice, options), doctest::Contains("more than the limit"), Error);
    options.cells = {4, 4, 4};
    options.periodic = true;
    CHECK_THROWS_WITH_AS(evaluate_block(kernel, lattice, options), doctest::Contains("a periodic block needs more than"),
                         Error);
}
