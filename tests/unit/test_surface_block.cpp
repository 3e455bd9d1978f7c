// Free-surface profiles against an independent half-space brute-force sum, and the
// particle block against the bulk shell sums and the surface profiles.
#include "analysis/surface_profile.hpp"
#include "block/particle_block.hpp"
#include "helpers.hpp"
#include "particles/particles_memory.hpp"
#include "support/error.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace sphkern;
using sphkern::test::shipped_kernel;

namespace {

struct LayerValue {
    double eps_rho, eps_gradp;
};

Lattice test_lattice(const std::string& name)
{
    for (const auto& shipped : shipped_lattice_names())
        if (shipped == name) return load_lattice(name);
    return load_lattice(test::lattice_file(name));
}

// A particle of motif site s at `depth` below a free surface normal to e, summed point by
// point over a large box: a lattice point x exists if its depth, depth + e . x, is >= 0.
// Densities first (needed by the Monaghan form), then the gradient.
struct HalfSpace {
    const Kernel& kernel;
    const Lattice& lattice;
    double k, a_p;
    Eigen::Vector3d e;
    static constexpr int box = 10;

    template <class Visit>
    void neighbours(int s, const Visit& visit) const
    {
        const int dim = lattice.dimension;
        for (int a = -box; a <= box; ++a)
            for (int b = -box; b <= box; ++b)
                for (int c = (dim == 3 ? -box : 0); c <= (dim == 3 ? box : 0); ++c)
                    for (std::size_t t = 0; t < lattice.motif.size(); ++t) {
                        Eigen::Vector3d x =
                            lattice.basis * (Eigen::Vector3d(a, b, c) + lattice.motif[t] - lattice.motif[s]);
                        double r = x.norm();
                        if (r < 1e-12 || r / k > kernel.support() * (1 + 1e-12)) continue;
                        visit(x, r, static_cast<int>(t));
                    }
    }
    double density(int s, double depth) const
    {
        const int dim = lattice.dimension;
        double sum = kernel.w(0, dim, k);
        neighbours(s, [&](const Eigen::Vector3d& x, double r, int) {
            if (depth + e.dot(x) > -1e-9) sum += kernel.w(r / k, dim, k);
        });
        return a_p * sum / std::pow(k, dim);
    }
    LayerValue at(int s, double depth_i, GradientForm form) const
    {
        const int dim = lattice.dimension;
        const double rho_i = density(s, depth_i);
        double gradient = 0;
        neighbours(s, [&](const Eigen::Vector3d& x, double r, int t) {
            double depth_j = depth_i + e.dot(x);
            if (depth_j < -1e-9) return;
            double weight = form == GradientForm::sum ? depth_i + depth_j
                            : form == GradientForm::difference
                                ? depth_j - depth_i
                                : rho_i * (depth_i / (rho_i * rho_i) + depth_j / std::pow(density(t, depth_j), 2));
            gradient += weight * kernel.dw(r / k, dim, k) * (-e.dot(x)) / r;
        });
        return {rho_i - 1, a_p * gradient / (std::pow(k, dim) * k) - 1};
    }
    // The depths of the occupied planes below a top plane holding site s, point by point.
    std::vector<double> plane_depths(int s, double down_to) const
    {
        std::vector<double> depths;
        const int dim = lattice.dimension, n = 2 * box;
        for (int a = -n; a <= n; ++a)
            for (int b = -n; b <= n; ++b)
                for (int c = (dim == 3 ? -n : 0); c <= (dim == 3 ? n : 0); ++c)
                    for (const auto& m : lattice.motif) {
                        double d = e.dot(lattice.basis * (Eigen::Vector3d(a, b, c) + m - lattice.motif[s]));
                        if (d > -1e-9 && d <= down_to) depths.push_back(std::max(d, 0.0));
                    }
        std::sort(depths.begin(), depths.end());
        depths.erase(std::unique(depths.begin(), depths.end(), [](double x, double y) { return y - x <= 1e-9; }),
                     depths.end());
        return depths;
    }
};

} // namespace

TEST_CASE("surface profiles equal a half-space brute-force sum, every form, every site, 2D and 3D")
{
    struct Case {
        const char* lattice;
        Eigen::Vector3d gravity;
    };
    const Case cases[] = {{"triangular", {0, -1, 0}},  {"square", {0, -1, 0}}, {"fcc", {0, 0, -1}},
                          {"hcp", {0, 0, -1}},         {"hcp", {-1, 0, 0}},    {"honeycomb", {0, -1, 0}},
                          {"honeycomb", {-1, 0, 0}},   {"kagome", {0, -1, 0}}, {"lieb", {0, -1, 0}},
                          {"skewed_pair", {0, -1, 0}}, {"diamond", {0, 0, -1}}};
    int multi_site_planes = 0;
    for (const auto& c : cases)
        for (const char* kernel_name : {"cubic_bspline", "wendland_c2"})
            for (auto form : {GradientForm::sum, GradientForm::difference, GradientForm::monaghan}) {
                auto lattice = test_lattice(c.lattice);
                Kernel kernel = shipped_kernel(kernel_name);
                double a_p = lattice.volume_coefficient("voronoi"), k = 1.15;
                HalfSpace brute{kernel, lattice, k, a_p, c.gravity};
                auto first = surface_profile(kernel, lattice, 0, a_p, c.gravity, k, 3, form);
                for (int termination = 0; termination < static_cast<int>(first.planes.types.size()); ++termination) {
                    auto profile = surface_profile(kernel, lattice, 0, a_p, c.gravity, k, 3, form, termination);
                    CAPTURE(std::string(c.lattice));
                    CAPTURE(c.gravity.transpose());
                    CAPTURE(kernel_name);
                    CAPTURE(std::string(gradient_form_name(form)));
                    CAPTURE(termination);
                    // The occupied planes, as they are.
                    const int top_site = profile.planes.types[static_cast<std::size_t>(termination)].sites[0];
                    auto depths = brute.plane_depths(top_site, profile.layers.back().depth + 1e-6);
                    REQUIRE(depths.size() == profile.layers.size());
                    for (const auto& layer : profile.layers) {
                        CHECK(layer.depth == doctest::Approx(depths[static_cast<std::size_t>(layer.n)]).epsilon(1e-12));
                        multi_site_planes += layer.sites.size() > 1;
                        for (const auto& v : layer.sites) {
                            auto expected = brute.at(v.site, layer.depth, form);
                            CHECK(v.eps_rho == doctest::Approx(expected.eps_rho).epsilon(1e-12));
                            CHECK(v.eps_gradp == doctest::Approx(expected.eps_gradp).epsilon(1e-12));
                        }
                    }
                    // A site that is a centre of inversion ends in the bulk of share/docs/method.md section 2;
                    // Monaghan's form divides by the SPH density there (when every site has the same).
                    bool equal_densities = true;
                    for (const auto& b : profile.bulk.sites)
                        equal_densities &= std::abs(b.eps_rho - profile.bulk.sites[0].eps_rho) < 1e-12;
                    for (const auto& v : profile.layers.back().sites) {
                        if (profile.first_moments[static_cast<std::size_t>(v.site)].norm() > 1e-9) continue;
                        if (form == GradientForm::monaghan && !equal_densities) continue;
                        auto b = HydrostaticErrors(kernel, lattice, v.site, a_p, c.gravity, k).at(k);
                        double gradp =
                            form == GradientForm::monaghan ? (1 + b.eps_gradp) / (1 + b.eps_rho) - 1 : b.eps_gradp;
                        CHECK(v.eps_rho == doctest::Approx(b.eps_rho).epsilon(1e-12));
                        CHECK(v.eps_gradp == doctest::Approx(gradp).epsilon(1e-12));
                        CHECK(profile.bulk.sites[static_cast<std::size_t>(v.site)].eps_gradp ==
                              doctest::Approx(gradp).epsilon(1e-12));
                    }
                }
            }
    CHECK(multi_site_planes > 0); // hcp along a: both sites on every plane
}

TEST_CASE("honeycomb under gravity -y: the occupied planes are 1 d and 0.5 d apart, not an even 0.5 d")
{
    auto lattice = test_lattice("honeycomb");
    auto profile = surface_profile(shipped_kernel("cubic_bspline"), lattice, 0, lattice.volume_coefficient("voronoi"),
                                   lattice.gravity, 1.2, 4, GradientForm::sum);
    REQUIRE(profile.layers.size() >= 4);
    CHECK(profile.layers[1].depth == doctest::Approx(1.0));
    CHECK(profile.layers[2].depth == doctest::Approx(1.5));
    CHECK(profile.layers[3].depth == doctest::Approx(2.5));
    CHECK(profile.layers[1].sites[0].site == 1);
    CHECK(profile.planes.types.size() == 2);
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
                         doctest::Contains("not normal to a family of lattice planes"), Error);
    // Along a lattice row is fine: the planes normal to x.
    CHECK_NOTHROW(surface_profile(kernel, lattice, 0, 1.0, Eigen::Vector3d(-1, 0, 0), 1.2, 3, GradientForm::sum));
}

TEST_CASE("block: interior particles equal the bulk shell sums, top layers the surface profile, site by site")
{
    struct Case {
        const char* lattice;
        std::array<long long, 3> cells;
    };
    for (const auto& c :
         {Case{"triangular", {16, 24, 1}}, Case{"fcc", {8, 8, 20}}, Case{"hcp", {8, 8, 11}}, Case{"bcc", {8, 8, 18}},
          Case{"honeycomb", {12, 16, 1}}, Case{"kagome", {10, 14, 1}}, Case{"hcp_a", {8, 8, 32}}})
        for (auto form : {GradientForm::sum, GradientForm::difference, GradientForm::monaghan}) {
            auto lattice = test_lattice(c.lattice);
            Kernel kernel = shipped_kernel("cubic_bspline");
            BlockOptions options;
            options.cells = c.cells;
            options.periodic = true;
            options.k = 1.2;
            options.a_p = lattice.volume_coefficient("voronoi");
            options.form = form;
            auto block = evaluate_block(kernel, lattice, options);
            const std::size_t per_site = block.particles() / static_cast<std::size_t>(lattice.sites());
            // The profile whose termination is the block's top plane.
            int top_site = -1;
            for (std::size_t i = 0; i < block.particles() && top_site < 0; ++i)
                if (block.layer[i] == 0) top_site = static_cast<int>(i / per_site);
            auto profile = surface_profile(kernel, lattice, top_site, options.a_p, block.gravity, options.k, 1, form);
            CAPTURE(std::string(c.lattice));
            CAPTURE(std::string(gradient_form_name(form)));
            const int deepest = *std::max_element(block.layer.begin(), block.layer.end());
            const int settled = static_cast<int>(profile.layers.size());
            int compared_top = 0, compared_bulk = 0;
            for (std::size_t i = 0; i < block.particles(); ++i) {
                const int n = block.layer[i], site = static_cast<int>(i / per_site);
                if (deepest - n < settled + 2) continue; // near the free bottom
                if (n < settled) {
                    const auto& sites = profile.layers[static_cast<std::size_t>(n)].sites;
                    auto v = std::find_if(sites.begin(), sites.end(),
                                          [&](const SiteLayerErrors& x) { return x.site == site; });
                    REQUIRE(v != sites.end()); // the block's plane n holds the profile's sites
                    CHECK(std::abs(block.eps_rho[i] - v->eps_rho) <= 1e-12 * (1 + std::abs(v->eps_rho)));
                    CHECK(std::abs(block.eps_gradp[i] - v->eps_gradp) <= 1e-12 * (1 + std::abs(v->eps_gradp)));
                    ++compared_top;
                } else {
                    auto expected =
                        HydrostaticErrors(kernel, lattice, site, options.a_p, block.gravity, options.k).at(options.k);
                    CHECK(std::abs(block.eps_rho[i] - expected.eps_rho) <= 1e-12);
                    CHECK(std::abs(block.eps_gradp[i] - profile.bulk.sites[static_cast<std::size_t>(site)].eps_gradp) <=
                          1e-12 * (1 + n));
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

TEST_CASE("block: each pair once equals every particle gathering its own (1e-13), free and periodic, every form, "
          "2D and 3D, and the same bits on 1, 2 and 7 threads")
{
    struct Case {
        const char* lattice;
        std::array<long long, 3> cells;
    };
    for (const auto& c : {Case{"triangular", {21, 17, 1}}, Case{"honeycomb", {13, 12, 1}}, Case{"fcc", {9, 8, 7}},
                          Case{"hcp", {8, 8, 5}}})
        for (bool periodic : {false, true})
            for (auto form : {GradientForm::sum, GradientForm::difference, GradientForm::monaghan}) {
                auto lattice = test_lattice(c.lattice);
                Kernel kernel = shipped_kernel("quartic_bspline");
                BlockOptions options;
                options.cells = c.cells, options.periodic = periodic, options.k = 1.3, options.form = form;
                options.threads = 1;
                CAPTURE(std::string(c.lattice));
                CAPTURE(periodic);
                CAPTURE(std::string(gradient_form_name(form)));
                options.each_pair_once = false;
                const auto gathered = evaluate_block(kernel, lattice, options);
                options.each_pair_once = true;
                const auto paired = evaluate_block(kernel, lattice, options);
                CHECK(paired.pair_interactions == gathered.pair_interactions);
                double worst = 0;
                for (std::size_t i = 0; i < paired.particles(); ++i) {
                    worst = std::max({worst, std::abs(paired.eps_rho[i] - gathered.eps_rho[i]),
                                      std::abs(paired.eps_gradp[i] - gathered.eps_gradp[i])});
                }
                CHECK(worst < 1e-13);
                CHECK(worst > 0); // the order of the terms differs: not the gather's bits
                for (int threads : {2, 7}) {
                    options.threads = threads;
                    const auto again = evaluate_block(kernel, lattice, options);
                    CHECK(again.eps_rho == paired.eps_rho);
                    CHECK(again.eps_gradp == paired.eps_gradp);
                }
            }
}

TEST_CASE("block sizes are checked before anything is allocated")
{
    auto lattice = load_lattice("fcc");
    Kernel kernel = shipped_kernel("cubic_bspline");
    BlockOptions options;
    options.k = 1.2;
    options.cells = {0, 10, 10};
    CHECK_THROWS_WITH_AS(evaluate_block(kernel, lattice, options), doctest::Contains("positive number of cells"),
                         Error);
    options.cells = {-3, 10, 10};
    CHECK_THROWS_WITH_AS(evaluate_block(kernel, lattice, options), doctest::Contains("positive number of cells"),
                         Error);
    options.cells = {100000, 100000, 100000};
    CHECK_THROWS_WITH_AS(evaluate_block(kernel, lattice, options), doctest::Contains("more than the limit"), Error);
    options.cells = {4, 4, 4};
    options.periodic = true;
    CHECK_THROWS_WITH_AS(evaluate_block(kernel, lattice, options),
                         doctest::Contains("a periodic block needs more than"), Error);
}

// Every pair of the block (and, for a periodic block, of its lateral images), summed
// directly: the block's density and gradient by brute force, independent of the engine.
struct BruteForceBlock {
    std::vector<double> eps_rho, eps_gradp;
};

BruteForceBlock brute_force_block(const Kernel& kernel, const Lattice& lattice, const BlockOptions& options,
                                  const BlockResult& block)
{
    const int dim = lattice.dimension;
    const std::size_t n = block.particles();
    const double k = options.k, reach = kernel.support() * k;
    const Eigen::Vector3d g = block.gravity;
    double top = -INFINITY;
    for (std::size_t i = 0; i < n; ++i)
        top = std::max(top, -g.dot(Eigen::Vector3d(block.x[i], block.y[i], block.z[i])));
    std::vector<Eigen::Vector3d> shifts{Eigen::Vector3d::Zero()};
    if (options.periodic) {
        shifts.clear();
        const int m = dim == 3 ? 1 : 0;
        for (int a = -1; a <= 1; ++a)
            for (int b = -m; b <= m; ++b)
                shifts.push_back(lattice.basis.col(0) * double(a * options.cells[0]) +
                                 lattice.basis.col(1) * double(b * options.cells[1]));
    }
    auto position = [&](std::size_t i) { return Eigen::Vector3d(block.x[i], block.y[i], block.z[i]); };
    auto depth = [&](const Eigen::Vector3d& p) { return top + g.dot(p); };
    const double kd = std::pow(k, dim);
    BruteForceBlock out{std::vector<double>(n), std::vector<double>(n)};
    for (std::size_t i = 0; i < n; ++i) {
        double sum = kernel.w(0, dim, k);
        for (std::size_t j = 0; j < n; ++j)
            for (const auto& s : shifts) {
                const double r = (position(j) + s - position(i)).norm();
                if (r > 0 && r <= reach) sum += kernel.w(r / k, dim, k);
            }
        out.eps_rho[i] = options.a_p * sum / kd - 1;
    }
    for (std::size_t i = 0; i < n; ++i) {
        double sum = 0;
        for (std::size_t j = 0; j < n; ++j)
            for (const auto& s : shifts) {
                const Eigen::Vector3d d = position(j) + s - position(i);
                const double r = d.norm();
                if (r == 0 || r > reach) continue;
                const double weight = gradient_form_weight(options.form, depth(position(i)), depth(position(j) + s),
                                                           1 + out.eps_rho[i], 1 + out.eps_rho[j]);
                sum += weight * kernel.dw(r / k, dim, k) * -g.dot(d) / r;
            }
        out.eps_gradp[i] = options.a_p * sum / (kd * k) - 1;
    }
    return out;
}

TEST_CASE("block: every particle equals a brute-force sum over all pairs, free and periodic, every form, 2D and 3D")
{
    struct Case {
        const char* lattice;
        std::array<long long, 3> cells;
    };
    for (const auto& c :
         {Case{"triangular", {9, 7, 1}}, Case{"honeycomb", {7, 6, 1}}, Case{"fcc", {6, 6, 4}}, Case{"hcp", {6, 6, 3}}})
        for (bool periodic : {false, true})
            for (auto form : {GradientForm::sum, GradientForm::difference, GradientForm::monaghan}) {
                auto lattice = test_lattice(c.lattice);
                Kernel kernel = shipped_kernel("wendland_c2");
                BlockOptions options;
                options.cells = c.cells;
                options.periodic = periodic;
                options.k = 1.1;
                options.a_p = lattice.volume_coefficient("voronoi");
                options.form = form;
                options.threads = 2;
                CAPTURE(std::string(c.lattice));
                CAPTURE(periodic);
                CAPTURE(std::string(gradient_form_name(form)));
                const auto block = evaluate_block(kernel, lattice, options);
                const auto expected = brute_force_block(kernel, lattice, options, block);
                double worst = 0;
                for (std::size_t i = 0; i < block.particles(); ++i)
                    worst = std::max(
                        {worst, std::abs(block.eps_rho[i] - expected.eps_rho[i]) / (1 + std::abs(expected.eps_rho[i])),
                         std::abs(block.eps_gradp[i] - expected.eps_gradp[i]) / (1 + std::abs(expected.eps_gradp[i]))});
                CHECK(worst < 1e-12);
            }
}

TEST_CASE("a periodic block at the engine's minimum width is refused by the block's own check, naming the cells")
{
    // 2 R k is within rounding of a whole number of cells here: the block's check and the
    // engine's must not disagree (the engine's message names h, which a block has not).
    struct Case {
        const char* lattice;
        double k;
    };
    for (const auto& c : {Case{"sc", 1.4999999999985003}, Case{"hcp", 1.5155444566212526}, Case{"fcc", 1.2}})
        for (long long n = 4; n <= 16; ++n) {
            auto lattice = load_lattice(c.lattice);
            Kernel kernel = shipped_kernel("cubic_bspline");
            BlockOptions options;
            options.cells = {n, n, 2};
            options.periodic = true;
            options.k = c.k;
            CAPTURE(std::string(c.lattice));
            CAPTURE(n);
            try {
                evaluate_block(kernel, lattice, options);
            } catch (const Error& e) {
                CHECK(std::string(e.what()).find("a periodic block needs more than") != std::string::npos);
            }
        }
}

TEST_CASE("a periodic block whose images overrun the memory budget is refused before anything is allocated")
{
    // 1 MiB at 200 bytes a point: 5242 points. 12 x 12 x 30 fcc cells are 4320 particles, within
    // it; with the images within reach of the sides they are more than twice that.
    set_memory_limit_gib(1.0 / 1024);
    struct Restore {
        ~Restore() { set_memory_limit_gib(0); } // the machine's budget again, however the case ends
    } restore;
    auto lattice = load_lattice("fcc");
    Kernel kernel = shipped_kernel("cubic_bspline");
    BlockOptions options;
    options.cells = {12, 12, 30};
    options.k = 1.2;
    CHECK_NOTHROW(evaluate_block(kernel, lattice, options)); // free sides: no images
    options.periodic = true;
    try {
        evaluate_block(kernel, lattice, options);
        FAIL("a periodic block over the budget was evaluated");
    } catch (const Error& e) {
        const std::string message = e.what();
        CHECK(message.find("the block asks for its particles and their periodic images") != std::string::npos);
        CHECK(message.find('\n') == std::string::npos);
        CHECK(e.code() == ExitCode::input);
    }
}
