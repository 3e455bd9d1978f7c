#include "stability/dispersion.hpp"

#include "kernels/kernel_validity.hpp"
#include "lattices/lattice_points.hpp"
#include "stability/stability_budget.hpp"
#include "support/error.hpp"
#include "support/process/interruption.hpp"
#include "support/text/value_checks.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>

namespace sphkern {

namespace {

// Calls f on each item, checking for a signal between chunks of 65536 (a large k has millions
// of neighbours): the inner loop stays as tight as it is without the check.
template <class List, class F>
void for_each_interruptible(const List& list, F&& f)
{
    constexpr std::size_t chunk = std::size_t{1} << 16;
    for (std::size_t begin = 0; begin < list.size(); begin += chunk) {
        throw_if_interrupted();
        const std::size_t end = std::min(list.size(), begin + chunk);
        for (std::size_t i = begin; i < end; ++i) f(list[i]);
    }
}

} // namespace

void check_gamma(double gamma, const std::string& what)
{
    // 2 / gamma enters the pressure terms: below 1e-6 it nears overflow (1e-320 gave -nan and "stable").
    if (!std::isfinite(gamma) || gamma < min_gamma || gamma > max_gamma)
        throw Error(ExitCode::usage,
                    fmt::format("{} {} is not allowed, expected a number in [1e-06, 1e+06]", what, gamma));
}

Eigen::Vector3d checked_wavevector(const std::vector<double>& components, int dimension, const std::string& what)
{
    if (static_cast<int>(components.size()) != dimension)
        throw Error(ExitCode::usage, fmt::format("{}: {} components, expected {} for a {}D lattice", what,
                                                 components.size(), dimension, dimension));
    Eigen::Vector3d kappa = Eigen::Vector3d::Zero();
    for (int i = 0; i < dimension; ++i) kappa[i] = components[static_cast<std::size_t>(i)];
    if (!std::isfinite(kappa.norm()) || kappa.norm() == 0 || kappa.norm() > 1e6)
        throw Error(ExitCode::usage,
                    fmt::format("{}: expected a non-zero wave vector with |kappa| <= 1e6 (in 1/d)", what));
    return kappa;
}

Dispersion::Dispersion(const Kernel& kernel, const Lattice& lattice, double k, double gamma, HModel h_model)
    : dim_(lattice.dimension), k_(k), gamma_(gamma), h_model_(h_model)
{
    check_inputs(kernel, lattice, k, gamma);
    mass_ = lattice.volume_per_site(); // rho0 = 1 with a_p voronoi; the spectrum does not depend on it
    basis_ = lattice.basis;
    const int n_sites = lattice.sites();
    for (int s = 0; s < n_sites; ++s)
        for (int t = 0; t < n_sites; ++t)
            offsets_.push_back(
                basis_ * (lattice.motif[static_cast<std::size_t>(t)] - lattice.motif[static_cast<std::size_t>(s)]));
    neighbours_.resize(static_cast<std::size_t>(n_sites));
    const HDerivatives self = h_derivatives(0, kernel.w(0, dim_, k), 0, 0, k, dim_);
    SiteSums first_site;
    first_site.Z = mass_ * self.dw_dh, first_site.Z2 = mass_ * self.d2w_dh2; // site 0: sum m dW/dh, sum m d2W/dh2
    std::array<int, 3> cell_max{};
    std::vector<double> densities;
    for (int s = 0; s < n_sites; ++s) {
        SiteSums sums = s == 0 ? first_site : SiteSums{};
        list_neighbours(kernel, lattice, s, sums, cell_max);
        check_site_at_rest(lattice, s, sums);
        if (s == 0) first_site = sums;
        densities.push_back(sums.density);
    }
    for (int a = 0; a < 3; ++a) cell_span_[a] = cell_max[a] - cell_min_[a] + 1;
    sum_long_wave_moments();
    density_ = densities[0];
    check_one_density(lattice, densities);
    set_coefficients(first_site.Z, first_site.Z2);
}

void Dispersion::check_inputs(const Kernel& kernel, const Lattice& lattice, double k, double gamma) const
{
    if (!std::isfinite(gamma) || gamma < min_gamma || gamma > max_gamma)
        fail_input(fmt::format("gamma = {} is not allowed, expected a number in [1e-06, 1e+06]", gamma));
    check_k(k, ValueSource::argument("k"));
    kernel.require_dimension(dim_, lattice.name);
    require_usable_kernel(kernel, dim_, k);
    // Every neighbour is kept (about 170 bytes each): a large k must not exhaust the memory.
    check_dispersion_neighbours(kernel, lattice, k);
}

void Dispersion::list_neighbours(const Kernel& kernel, const Lattice& lattice, int s, SiteSums& sums,
                                 std::array<int, 3>& cell_max)
{
    const double h = k_, hd = std::pow(h, dim_);
    const bool adaptive = h_model_ == HModel::adaptive;
    const Eigen::Matrix3d to_cells = basis_.inverse();
    auto& list = neighbours_[static_cast<std::size_t>(s)];
    sums.density = mass_ * kernel.w(0, dim_, k_) / hd;
    std::size_t visited = 0;
    for_each_lattice_point_of_site(lattice.basis, dim_, lattice.motif, s, kernel.support() * h * (1 + support_edge),
                                   [&](const Eigen::Vector3d& x, int t) {
                                       // A large k has millions of neighbours: a signal is answered while they are
                                       // listed.
                                       if ((++visited & 0xFFFF) == 0) throw_if_interrupted();
                                       const double q = x.norm() / h;
                                       if (!kernel.inside(q)) return;
                                       const double w = kernel.w(q, dim_, k_) / hd;
                                       const double dw = kernel.dw(q, dim_, k_) / (hd * h);
                                       const double d2w = kernel.d2w(q, dim_, k_) / (hd * h * h);
                                       if (!std::isfinite(w)) fail_non_finite_kernel(kernel, "W", q, dim_, k_);
                                       if (!std::isfinite(dw)) fail_non_finite_kernel(kernel, "dW/dr", q, dim_, k_);
                                       if (!std::isfinite(d2w)) fail_non_finite_kernel(kernel, "d2W/dr2", q, dim_, k_);
                                       Neighbour n = neighbour_at(x, s, t, to_cells, dw, d2w, cell_max);
                                       if (adaptive) {
                                           const HDerivatives dh =
                                               h_derivatives(q, w * hd, dw * hd * h, d2w * hd * h * h, h, dim_);
                                           n.h_gradient = -mass_ * dh.dgrad_dh * (x / x.norm());
                                           sums.first_h += n.h_gradient;
                                           if (s == 0) sums.Z += mass_ * dh.dw_dh, sums.Z2 += mass_ * dh.d2w_dh2;
                                       }
                                       sums.density += mass_ * w;
                                       sums.first += n.gradient;
                                       list.push_back(n);
                                   });
}

Dispersion::Neighbour Dispersion::neighbour_at(const Eigen::Vector3d& x, int s, int t, const Eigen::Matrix3d& to_cells,
                                               double dw, double d2w, std::array<int, 3>& cell_max)
{
    const double r = x.norm();
    const Eigen::Vector3d e = x / r; // r_ij = x_i - x_j = -x, and H is even
    Neighbour n;
    n.x = x;
    n.site = t;
    const Eigen::Vector3d offset = offsets_[static_cast<std::size_t>(s * sites() + t)];
    const Eigen::Vector3d cell = to_cells * (x - offset);
    for (int a = 0; a < 3; ++a) {
        n.cell[a] = a < dim_ ? static_cast<int>(std::lround(cell[a])) : 0;
        cell_min_[a] = std::min(cell_min_[a], n.cell[a]);
        cell_max[a] = std::max(cell_max[a], n.cell[a]);
    }
    const Eigen::Vector3d back = basis_ * Eigen::Vector3d(n.cell[0], n.cell[1], n.cell[2]) + offset;
    if ((back - x).norm() > 1e-9 * std::max(1.0, x.norm())) integer_cells_ = false;
    n.gradient = -mass_ * dw * e;
    n.hessian = mass_ * (d2w * e * e.transpose() + (dw / r) * (Eigen::Matrix3d::Identity() - e * e.transpose()));
    return n;
}

void Dispersion::check_site_at_rest(const Lattice& lattice, int s, const SiteSums& sums) const
{
    const double h = k_, density = sums.density;
    // Against grad W ~ rho / h: a relative measure would amplify rounding where every W' ~ 0.
    if (sums.first.norm() > 1e-9 * density / h)
        fail_input(fmt::format("site {} of lattice {} is not a centre of symmetry: the SPH pressure force on it does "
                               "not vanish at rest (first moment {:.3g}), so the lattice is no equilibrium to "
                               "linearise about; stability needs sites whose neighbourhoods cancel",
                               s, lattice.name, sums.first.norm() * h / density));
    if (sums.first_h.norm() > 1e-9 * density / (h * h))
        fail_input(fmt::format("site {} of lattice {} is not a centre of symmetry: the h-derivative of its first "
                               "moment does not vanish ({:.3g}), so adaptive h moves it at rest; stability with "
                               "adaptive h needs sites whose neighbourhoods cancel at every h",
                               s, lattice.name, sums.first_h.norm() * h * h / density));
}

void Dispersion::sum_long_wave_moments()
{
    for (auto& q : hessian_moments_) q.setZero();
    std::size_t moments = 0;
    for (const auto& nb : neighbours_[0]) {
        if ((++moments & 0xFFFF) == 0) throw_if_interrupted();
        gradient_moment_ += nb.gradient * nb.x.transpose();
        h_gradient_moment_ += nb.h_gradient * nb.x.transpose();
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
                hessian_moments_[static_cast<std::size_t>(3 * a + b)] += 0.5 * nb.x[a] * nb.x[b] * nb.hessian;
    }
}

void Dispersion::check_one_density(const Lattice& lattice, const std::vector<double>& densities) const
{
    // A k so small that h^D underflows: no neighbour, an infinite (or huge) density and pressure
    // terms of 0, which a scan over k read as "stable" with omega^2 = 0.
    if (!std::isfinite(density_) || !(density_ > 0) || !std::isnormal(1 / (density_ * density_)))
        fail_input(fmt::format("k = {:.6g} is outside what this kernel and lattice {} can be evaluated at: the SPH "
                               "density is {:.3g} times rho0 and the pressure terms underflow (expected k of order 1)",
                               k_, lattice.name, density_ / mass_));
    for (std::size_t s = 1; s < densities.size(); ++s)
        if (std::abs(densities[s] - density_) > 1e-9 * density_)
            fail_input(
                fmt::format("the sites of lattice {} do not see one SPH density (site 0: {:.10g}, site {}: {:.10g} "
                            "times rho0 at k = {}): one pressure cannot hold them at rest, so stability is "
                            "defined only for lattices whose sites are equivalent",
                            lattice.name, density_ / mass_, s, densities[s] / mass_, k_));
}

void Dispersion::set_coefficients(double Z, double Z2)
{
    coefficients_ = dispersion_coefficients(h_model_, gamma_, density_, k_, dim_, Z, Z2);
    c_gradient_ = coefficients_.gradient;
    c_cross_ = coefficients_.cross;
    c_hessian_ = coefficients_.hessian;
    // Never a non-finite omega^2 printed as a result: the coefficients of every matrix are finite.
    const bool alone =
        std::all_of(neighbours_.begin(), neighbours_.end(), [](const auto& list) { return list.empty(); });
    if (alone && (!std::isfinite(c_gradient_) || !std::isfinite(c_cross_) || !std::isfinite(c_hessian_)))
        fail_input(
            fmt::format("k = {}: no neighbour lies inside the support, so no SPH force holds a particle and the "
                        "linear stability has no meaning ({} h: Omega = {:.3g}); expected a k whose support reaches "
                        "the nearest neighbours",
                        k_, h_model_name(h_model_), coefficients_.omega));
    if (!std::isfinite(c_gradient_) || !std::isfinite(c_cross_) || !std::isfinite(c_hessian_))
        fail_input(
            fmt::format("gamma = {} and the SPH density {:.6g} at k = {} give pressure coefficients that are not "
                        "finite numbers",
                        gamma_, density_, k_));
}

double Dispersion::eta() const { return k_ / std::pow(mass_ / density_, 1.0 / dim_); }

bool Dispersion::fast_phases(const Eigen::Vector3d& kappa) const
{
    return integer_cells_ && kappa.head(dim_).norm() >= fast_phase_min;
}

std::vector<std::complex<double>> Dispersion::cell_phases(const Eigen::Vector3d& kappa) const
{
    std::vector<std::complex<double>> table;
    table.reserve(static_cast<std::size_t>(cell_span_[0] + cell_span_[1] + cell_span_[2]));
    for (int a = 0; a < 3; ++a) {
        const double step = a < dim_ ? kappa.dot(basis_.col(a)) : 0;
        for (int n = cell_min_[a]; n < cell_min_[a] + cell_span_[a]; ++n) table.push_back(std::polar(1.0, n * step));
    }
    return table;
}

std::complex<double> Dispersion::phase_of(const Neighbour& nb, const std::vector<std::complex<double>>& table) const
{
    const std::size_t i = static_cast<std::size_t>(nb.cell[0] - cell_min_[0]);
    const std::size_t j = static_cast<std::size_t>(cell_span_[0] + nb.cell[1] - cell_min_[1]);
    const std::size_t l = static_cast<std::size_t>(cell_span_[0] + cell_span_[1] + nb.cell[2] - cell_min_[2]);
    return table[i] * table[j] * table[l];
}

Eigen::MatrixXcd Dispersion::matrix(const Eigen::Vector3d& kappa) const
{
    throw_if_interrupted(); // one matrix sums every neighbour: at a large k that takes seconds
    const int n = sites(), D = dim_;
    // Per site pair, in fixed-size sums: A_st (a vector) and the block of B0 - B, summed as
    // H (1 - e) within a site so that long waves lose no digits to cancellation.
    std::vector<Eigen::Vector3cd> A(static_cast<std::size_t>(n * n), Eigen::Vector3cd::Zero());
    std::vector<Eigen::Vector3cd> Ah(A); // of the h-derivatives of the gradients (adaptive h)
    const bool adaptive = h_model_ == HModel::adaptive;
    std::vector<Eigen::Matrix3cd> B(static_cast<std::size_t>(n * n), Eigen::Matrix3cd::Zero());
    const bool fast = fast_phases(kappa);
    const auto table = fast ? cell_phases(kappa) : std::vector<std::complex<double>>{};
    std::vector<std::complex<double>> offset_phase;
    for (const auto& o : offsets_) offset_phase.push_back(std::polar(1.0, kappa.dot(o)));
    std::size_t summed = 0;
    for (int s = 0; s < n; ++s)
        for (const auto& nb : neighbours_[static_cast<std::size_t>(s)]) {
            if ((++summed & 0xFFFF) == 0) throw_if_interrupted();
            const auto pair = static_cast<std::size_t>(s * n + nb.site);
            std::complex<double> e; // exp(-i kappa.r_ij) = exp(i kappa.x), r_ij = -x
            double one_minus_cos;
            if (fast) {
                e = phase_of(nb, table) * offset_phase[pair];
                one_minus_cos = 1 - e.real();
            } else {
                const double phase = kappa.dot(nb.x), half = std::sin(0.5 * phase);
                e = {std::cos(phase), std::sin(phase)};
                one_minus_cos = 2 * half * half;
            }
            A[pair] += e * nb.gradient;
            if (adaptive) Ah[pair] += e * nb.h_gradient;
            if (nb.site == s) {
                B[pair] += std::complex<double>(one_minus_cos, -e.imag()) * nb.hessian;
            } else {
                B[static_cast<std::size_t>(s * n + s)] += nb.hessian;
                B[pair] -= e * nb.hessian;
            }
        }
    Eigen::MatrixXcd columns = Eigen::MatrixXcd::Zero(D * n, n), M = Eigen::MatrixXcd::Zero(D * n, D * n);
    Eigen::MatrixXcd h_columns = Eigen::MatrixXcd::Zero(D * n, n);
    for (int s = 0; s < n; ++s)
        for (int t = 0; t < n; ++t) {
            const auto pair = static_cast<std::size_t>(s * n + t);
            columns.block(D * s, t, D, 1) = A[pair].head(D);
            h_columns.block(D * s, t, D, 1) = Ah[pair].head(D);
            M.block(D * s, D * t, D, D) = c_hessian_ * B[pair].topLeftCorner(D, D);
        }
    M += c_gradient_ * columns * columns.adjoint();
    if (adaptive) {
        const Eigen::MatrixXcd cross = columns * h_columns.adjoint();
        M -= c_cross_ * (cross + cross.adjoint());
    }
    return M;
}

std::vector<double> Dispersion::omega2(const Eigen::Vector3d& kappa) const
{
    // Every search calls this: at a large k one call sums millions of neighbours, and the
    // searches between two checks of their own make thousands of calls. One site checks for a
    // signal per chunk of neighbours; several go through matrix(), which checks too.
    if (sites() == 1) {
        // One site: A = -i S and B0 - B = T are real; a fixed-size solver, no allocation.
        Eigen::Matrix3d S3 = Eigen::Matrix3d::Zero();
        Eigen::Vector3d S = Eigen::Vector3d::Zero(), Sh = Eigen::Vector3d::Zero();
        const bool adaptive = h_model_ == HModel::adaptive;
        Eigen::Matrix3d T = Eigen::Matrix3d::Zero();
        if (fast_phases(kappa)) {
            const auto table = cell_phases(kappa);
            for_each_interruptible(neighbours_[0], [&](const Neighbour& nb) {
                const auto e = phase_of(nb, table);
                S += e.imag() * nb.gradient;
                if (adaptive) Sh += e.imag() * nb.h_gradient;
                T += (1 - e.real()) * nb.hessian;
            });
        } else {
            for_each_interruptible(neighbours_[0], [&](const Neighbour& nb) {
                const double phase = kappa.dot(nb.x), half = std::sin(0.5 * phase);
                S += std::sin(phase) * nb.gradient;
                if (adaptive) Sh += std::sin(phase) * nb.h_gradient;
                T += 2 * half * half * nb.hessian;
            });
        }
        S3 = c_gradient_ * S * S.transpose() + c_hessian_ * T;
        if (adaptive) S3 -= c_cross_ * (S * Sh.transpose() + Sh * S.transpose());
        if (dim_ == 2) {
            Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver;
            solver.computeDirect(S3.topLeftCorner<2, 2>().eval(), Eigen::EigenvaluesOnly);
            return {solver.eigenvalues()[0], solver.eigenvalues()[1]};
        }
        if (dim_ == 1) return {S3(0, 0)};
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
        solver.computeDirect(S3, Eigen::EigenvaluesOnly);
        return {solver.eigenvalues()[0], solver.eigenvalues()[1], solver.eigenvalues()[2]};
    }
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd> solver(matrix(kappa), Eigen::EigenvaluesOnly);
    const auto& v = solver.eigenvalues();
    return std::vector<double>(v.data(), v.data() + v.size());
}

Eigen::Matrix3d Dispersion::long_wave_stiffness(const Eigen::Vector3d& n) const
{
    const Eigen::Vector3d e = n.normalized();
    Eigen::Matrix3d t = Eigen::Matrix3d::Zero();
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) t += e[a] * e[b] * hessian_moments_[static_cast<std::size_t>(3 * a + b)];
    return t; // rho0 = 1
}

Eigen::Matrix3d Dispersion::long_wave_matrix(const Eigen::Vector3d& n) const
{
    const Eigen::Vector3d s = gradient_moment_ * n.normalized(), sh = h_gradient_moment_ * n.normalized();
    return c_gradient_ * s * s.transpose() - c_cross_ * (s * sh.transpose() + sh * s.transpose()) +
           c_hessian_ * long_wave_stiffness(n);
}

DispersionModes Dispersion::modes(const Eigen::Vector3d& kappa) const
{
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd> solver(matrix(kappa));
    DispersionModes result;
    const double norm = kappa.head(dim_).norm();
    for (int b = 0; b < branches(); ++b) {
        result.omega2.push_back(solver.eigenvalues()[b]);
        Eigen::VectorXcd v = solver.eigenvectors().col(b);
        // A global phase that makes the largest component real and positive: reproducible output.
        Eigen::Index largest = 0;
        v.cwiseAbs().maxCoeff(&largest);
        if (std::abs(v[largest]) > 0) v *= std::abs(v[largest]) / v[largest];
        double along = 0;
        if (norm > 0)
            for (int s = 0; s < sites(); ++s) {
                std::complex<double> p = 0;
                for (int a = 0; a < dim_; ++a) p += kappa[a] / norm * v[dim_ * s + a];
                along += std::norm(p);
            }
        result.modes.push_back(v);
        result.longitudinal.push_back(along);
    }
    return result;
}

} // namespace sphkern
