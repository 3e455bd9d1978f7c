// Adaptive h: the dispersion matrix of grad-h SPH (h_i = eta (m/rho_i)^(1/D)) against a direct
// computation: a periodic block displaced by a small plane wave, h and rho solved
// self-consistently per particle by Newton's method, the accelerations of the grad-h momentum
// equation summed directly, omega^2 from central differences.
#include "helpers.hpp"
#include "stability/dispersion.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <complex>

using namespace sphkern;
using namespace sphkern::test;

namespace {

struct Pair {
    std::size_t j;
    Eigen::Vector3d shift; // the periodic image: r_ij = x_i - x_j - shift
};

// A periodic block of equal masses, with its candidate neighbours found once at rest.
struct Block {
    const Kernel& kernel;
    int dim;
    double k, mass, eta, gamma, pressure_constant;
    std::vector<std::vector<Pair>> pairs;

    double W(double r, double h) const { return kernel.inside(r / h) ? kernel.w(r / h, dim, k) / std::pow(h, dim) : 0; }
    double dW_dr(double r, double h) const
    {
        return kernel.inside(r / h) ? kernel.dw(r / h, dim, k) / std::pow(h, dim + 1) : 0;
    }
    double dW_dh(double r, double h) const { return -(dim * W(r, h) + r * dW_dr(r, h)) / h; }

    // rho_i(h) = sum_j m W(r_ij, h) and its h-derivative.
    std::pair<double, double> density(const std::vector<Eigen::Vector3d>& x, std::size_t i, double h) const
    {
        double rho = mass * W(0, h), drho = mass * dW_dh(0, h);
        for (const auto& p : pairs[i]) {
            const double r = (x[i] - x[p.j] - p.shift).norm();
            rho += mass * W(r, h);
            drho += mass * dW_dh(r, h);
        }
        return {rho, drho};
    }

    // h_i with rho_i(h_i) = m (eta / h_i)^D, by Newton's method to rounding.
    double smoothing_length(const std::vector<Eigen::Vector3d>& x, std::size_t i) const
    {
        double h = k;
        for (int iteration = 0; iteration < 50; ++iteration) {
            const auto [rho, drho] = density(x, i, h);
            const double target = mass * std::pow(eta / h, dim);
            const double step = (rho - target) / (drho + dim * target / h);
            h -= step;
            if (std::abs(step) < 1e-15 * h) break;
        }
        return h;
    }

    std::vector<Eigen::Vector3d> accelerations(const std::vector<Eigen::Vector3d>& x) const
    {
        const std::size_t n = x.size();
        std::vector<double> h(n), rho(n), factor(n); // factor = P / (Omega rho^2)
        for (std::size_t i = 0; i < n; ++i) {
            h[i] = smoothing_length(x, i);
            const auto [r, dr] = density(x, i, h[i]);
            rho[i] = r;
            const double Omega = 1 + h[i] * dr / (dim * r);
            factor[i] = pressure_constant * std::pow(r, gamma) / (Omega * r * r);
        }
        std::vector<Eigen::Vector3d> a(n, Eigen::Vector3d::Zero());
        for (std::size_t i = 0; i < n; ++i)
            for (const auto& p : pairs[i]) {
                const Eigen::Vector3d r = x[i] - x[p.j] - p.shift;
                const double d = r.norm();
                a[i] -= mass * (factor[i] * dW_dr(d, h[i]) + factor[p.j] * dW_dr(d, h[p.j])) * (r / d);
            }
        return a;
    }
};

void compare_adaptive(const Kernel& kernel, const Lattice& lattice, double k, int cells, const Eigen::Vector3d& m)
{
    const int dim = lattice.dimension;
    const double gamma = 5.0 / 3.0;
    const Dispersion dispersion(kernel, lattice, k, gamma, HModel::adaptive);
    const Eigen::Matrix3d b = 2 * M_PI * lattice.basis.inverse().transpose();
    const Eigen::Vector3d kappa = b * m / cells;
    Eigen::Matrix3d box = lattice.basis * cells;
    if (dim == 2) box.col(2).setZero();
    std::vector<Eigen::Vector3d> x;
    std::vector<int> site;
    for (int a = 0; a < cells; ++a)
        for (int c = 0; c < cells; ++c)
            for (int e = 0; e < (dim == 3 ? cells : 1); ++e)
                for (int s = 0; s < lattice.sites(); ++s) {
                    x.push_back(lattice.basis * (Eigen::Vector3d(a, c, e) + lattice.motif[s]));
                    site.push_back(s);
                }
    const double mass = lattice.volume_per_site(), rho_eq = dispersion.density_ratio() * mass;
    Block block{kernel, dim, k, mass, dispersion.eta(), gamma, std::pow(rho_eq, 1 - gamma) / gamma, {}};
    const double reach = kernel.support() * k * 1.01; // h moves by O(1e-5) at most
    block.pairs.resize(x.size());
    for (std::size_t i = 0; i < x.size(); ++i)
        for (std::size_t j = 0; j < x.size(); ++j)
            for (int a = -1; a <= 1; ++a)
                for (int c = -1; c <= 1; ++c)
                    for (int e = (dim == 3 ? -1 : 0); e <= (dim == 3 ? 1 : 0); ++e) {
                        const Eigen::Vector3d shift = box * Eigen::Vector3d(a, c, e);
                        const double d = (x[i] - x[j] - shift).norm();
                        if (d > 0 && d < reach) block.pairs[i].push_back({j, shift});
                    }
    // At rest: h = k d everywhere and no force.
    CHECK(block.smoothing_length(x, 0) == doctest::Approx(k).epsilon(1e-12));
    double rest = 0;
    for (const auto& v : block.accelerations(x)) rest = std::max(rest, v.norm());
    CHECK(rest < 1e-12);
    const auto modes = dispersion.modes(kappa);
    const auto fixed = Dispersion(kernel, lattice, k, gamma).omega2(kappa);
    const double eps = 1e-5;
    double differs = 0; // from the fixed-h spectrum: the test must see the grad-h terms
    for (int branch = 0; branch < dispersion.branches(); ++branch) {
        const Eigen::VectorXcd& xi = modes.modes[branch];
        auto displaced = [&](double sign) {
            std::vector<Eigen::Vector3d> y = x;
            for (std::size_t i = 0; i < x.size(); ++i) {
                const std::complex<double> phase(std::cos(kappa.dot(x[i])), std::sin(kappa.dot(x[i])));
                for (int a = 0; a < dim; ++a) y[i][a] += sign * eps * (xi[dim * site[i] + a] * phase).real();
            }
            return block.accelerations(y);
        };
        const auto plus = displaced(1), minus = displaced(-1);
        double worst = 0, scale = 0;
        for (std::size_t i = 0; i < x.size(); ++i) {
            const std::complex<double> phase(std::cos(kappa.dot(x[i])), std::sin(kappa.dot(x[i])));
            for (int a = 0; a < dim; ++a) {
                const double measured = (plus[i][a] - minus[i][a]) / (2 * eps);
                const double predicted = -modes.omega2[branch] * (xi[dim * site[i] + a] * phase).real();
                worst = std::max(worst, std::abs(measured - predicted));
                scale = std::max(scale, std::abs(predicted));
            }
        }
        differs = std::max(differs, std::abs(modes.omega2[branch] - fixed[branch]));
        CHECK_MESSAGE(worst < 1e-7 * std::max(1.0, scale), lattice.name << " " << kernel.name() << " branch " << branch
                                                                        << " omega2 " << modes.omega2[branch]
                                                                        << " worst " << worst);
    }
    CHECK_MESSAGE(differs > 1e-4,
                  lattice.name << " " << kernel.name() << ": adaptive and fixed h agree to " << differs);
}

} // namespace

TEST_CASE("adaptive h: the dispersion matrix matches directly summed grad-h SPH accelerations")
{
    for (const char* kernel_name : {"cubic_bspline", "wendland_c2"}) {
        const Kernel kernel = shipped_kernel(kernel_name);
        compare_adaptive(kernel, load_lattice("sc"), 1.1, 6, {1, 2, 0});
        compare_adaptive(kernel, load_lattice("sc"), 1.1, 6, {3, 0, 0});
        compare_adaptive(kernel, load_lattice("fcc"), 1.05, 8, {1, 3, -2});
        compare_adaptive(kernel, load_lattice("triangular"), 1.2, 8, {2, 3, 0});
    }
    compare_adaptive(shipped_kernel("wendland_c2"), load_lattice("bcc"), 1.0, 5, {1, 2, 0});
    compare_adaptive(shipped_kernel("cubic_bspline"), load_lattice("hcp"), 1.05, 5, {1, 0, 1});
}

TEST_CASE("adaptive h: eta and the grad-h factor at rest follow from the lattice's SPH density")
{
    const Kernel kernel = shipped_kernel("cubic_bspline");
    const auto lattice = load_lattice("fcc");
    const double k = 1.2;
    const Dispersion d(kernel, lattice, k, 5.0 / 3.0, HModel::adaptive);
    // eta^D m / rho = h^D: with m = volume per site (rho0 = 1), eta = k (rho / rho0)^(1/3).
    CHECK(d.eta() == doctest::Approx(k * std::cbrt(d.density_ratio())).epsilon(1e-14));
    CHECK(d.grad_h_factor() != doctest::Approx(1).epsilon(1e-6));
    CHECK(Dispersion(kernel, lattice, k, 5.0 / 3.0).grad_h_factor() == 1);
}
