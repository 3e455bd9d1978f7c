// Lattices with several sites, and every direction: per-site errors, the gradient-error
// tensor and the first moment against a brute-force sum over explicit lattice points
// (kagome, Lieb, honeycomb, diamond, hcp and a lattice without inversion centres), and
// the support edge.
#include "analysis/acceptance.hpp"
#include "analysis/site_errors.hpp"
#include "helpers.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace sphkern;
using sphkern::test::shipped_kernel;

namespace {

struct BruteSite {
    double eps_rho;
    Eigen::Matrix3d tensor; // E
    Eigen::Vector3d first;  // m1
    int neighbours;
};

// Written out from the definitions: every point x_j = B (n + m_t - m_s) of a box around
// site s, inside the support (q <= R, the edge included).
BruteSite brute_force_site(const Kernel& kernel, const Lattice& lattice, int s, double k, double a_p)
{
    const int dim = lattice.dimension, n = 8;
    const double R = kernel.support(), kd = std::pow(k, dim);
    BruteSite b{kernel.w(0, dim, k), Eigen::Matrix3d::Zero(), Eigen::Vector3d::Zero(), 0};
    for (const auto& mt : lattice.motif)
        for (int a = -n; a <= n; ++a)
            for (int c = -n; c <= n; ++c)
                for (int e = (dim == 3 ? -n : 0); e <= (dim == 3 ? n : 0); ++e) {
                    Eigen::Vector3d x = lattice.basis * (Eigen::Vector3d(a, c, e) + mt - lattice.motif[s]);
                    double r = x.norm();
                    if (r < 1e-12 || r / k > R * (1 + 1e-12)) continue;
                    const Eigen::Vector3d u = x / r;
                    const double dw = kernel.dw(r / k, dim, k);
                    b.eps_rho += kernel.w(r / k, dim, k);
                    b.tensor += r * dw * u * u.transpose();
                    b.first += dw * u;
                    b.neighbours += 1;
                }
    b.eps_rho = a_p * b.eps_rho / kd - 1;
    b.tensor *= -a_p / (kd * k);
    b.tensor.topLeftCorner(dim, dim) -= Eigen::MatrixXd::Identity(dim, dim);
    b.first *= a_p / (kd * k);
    return b;
}

} // namespace

TEST_CASE("every site's errors, tensor and first moment equal a brute-force sum")
{
    int compared = 0;
    bool nonzero_first_moment = false, anisotropic = false;
    for (const std::string name : {"kagome", "lieb", "honeycomb", "diamond", "skewed_pair", "hcp"}) {
        auto lattice = name == "hcp" ? load_lattice("hcp") : load_lattice(test::lattice_file(name));
        const double a_p = lattice.volume_coefficient("voronoi");
        for (const char* kernel_name : {"cubic_bspline", "wendland_c4", "super_gaussian"}) {
            Kernel kernel = shipped_kernel(kernel_name);
            auto sites = errors_per_site(kernel, lattice, every_site(lattice), a_p, lattice.gravity, 1.3);
            for (double k : {0.9, 1.0, 1.1, 1.3})
                for (const auto& errors : sites) {
                    CAPTURE(name);
                    CAPTURE(kernel_name);
                    CAPTURE(k);
                    CAPTURE(errors->site());
                    auto report = site_report(*errors, k);
                    auto expected = brute_force_site(kernel, lattice, errors->site(), k, a_p);
                    CHECK(report.values.neighbours == expected.neighbours);
                    CHECK(report.values.eps_rho == doctest::Approx(expected.eps_rho).epsilon(1e-12));
                    CHECK((report.gradient.tensor - expected.tensor).norm() <= 1e-12 * (1 + expected.tensor.norm()));
                    CHECK((report.gradient.first_moment - expected.first).norm() <=
                          1e-12 * (1 + expected.first.norm()));
                    // Along gravity, the tensor gives the paper's error and the lateral part.
                    const Eigen::Vector3d e = lattice.gravity;
                    CHECK(report.values.eps_gradp == doctest::Approx(e.dot(expected.tensor * e)).epsilon(1e-12));
                    const Eigen::Vector3d lateral = expected.tensor * e - e.dot(expected.tensor * e) * e;
                    CHECK(std::abs(report.values.lateral - lateral.norm()) <= 1e-12);
                    nonzero_first_moment |= expected.first.norm() > 0.1;
                    anisotropic |= report.gradient.eigenvalues.back() - report.gradient.eigenvalues.front() > 0.1;
                    ++compared;
                }
        }
    }
    CHECK(compared == 4 * 3 * (3 + 3 + 2 + 2 + 2 + 2));
    CHECK(nonzero_first_moment); // the skewed pair has no centre of inversion
    CHECK(anisotropic);          // kagome and Lieb sites see direction-dependent gradients
}

TEST_CASE("the tensor's eigenvalues bound eps_gradP over directions, and the every-direction verdict is the stricter")
{
    auto lattice = load_lattice("hex_prism");
    Kernel kernel = shipped_kernel("liu_quartic");
    const double a_p = lattice.volume_coefficient("voronoi");
    HydrostaticErrors z(kernel, lattice, 0, a_p, Eigen::Vector3d(0, 0, -1), 1.3);
    for (double k : {0.85, 0.95, 1.2}) {
        auto g = z.tensor(k);
        for (const Eigen::Vector3d& e :
             {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 0, -1), Eigen::Vector3d(1, 2, 3).normalized(),
              Eigen::Vector3d(-2, 1, 0.5).normalized()}) {
            HydrostaticErrors along(kernel, lattice, 0, a_p, e, 1.3);
            const double v = along.at(k).eps_gradp;
            CHECK(v >= g.eigenvalues.front() - 1e-12);
            CHECK(v <= g.eigenvalues.back() + 1e-12);
        }
    }
    // Every direction at once passes only where gravity along z and along x both pass.
    const AcceptanceRule along{0.01, Direction::gravity, false}, every{0.01, Direction::every, false};
    HydrostaticErrors x(kernel, lattice, 0, a_p, Eigen::Vector3d(1, 0, 0), 1.3);
    auto both = evaluate_acceptance({&z}, 0.75, 1.3, every);
    for (const auto& interval : both.intervals) {
        const double k = 0.5 * (interval.from + interval.to);
        CHECK(acceptance_error(z, k, along) <= 0.01);
        CHECK(acceptance_error(x, k, along) <= 0.01);
    }
}

TEST_CASE("a neighbour exactly on the support edge is inside, whatever the rounding of its shell")
{
    // The 3 d shell of the triangular lattice comes out as 3.0000000000000004; at k = 1 the
    // truncated super-Gaussian (R = 3, W(3) != 0) must count it: 6 + 6 + 6 + 12 + 6 = 36 neighbours.
    auto lattice = load_lattice("triangular");
    Kernel kernel = shipped_kernel("super_gaussian");
    const double a_p = lattice.volume_coefficient("voronoi");
    HydrostaticErrors errors(kernel, lattice, 0, a_p, lattice.gravity, 1.0);
    auto v = errors.at(1.0);
    CHECK(v.neighbours == 36);
    auto expected = brute_force_site(kernel, lattice, 0, 1.0, a_p);
    CHECK(expected.neighbours == 36);
    CHECK(v.eps_rho == doctest::Approx(expected.eps_rho).epsilon(1e-13));
    CHECK(kernel.w_truncated(3.0000000000000004, 2, 1.0) == kernel.w(3.0000000000000004, 2, 1.0));
    CHECK(kernel.w_truncated(3.00001, 2, 1.0) == 0.0);
}
