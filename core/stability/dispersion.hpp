// The linearised SPH equations of a lattice at rest (the method document, "Linear
// stability"): for a plane-wave displacement xi_s exp(i kappa.x) of every site s,
//   omega^2 xi = [ (c^2 - 2P/rho) A A^H / rho^2 + (2P/rho^2) (B0 - B) ] xi,
// with A_st = m sum_{j in t} grad W(r_ij) exp(-i kappa.r_ij) (a vector per site pair),
// B_st = m sum_{j in t} H(r_ij) exp(-i kappa.r_ij), H = W'' r^r^T + (W'/r)(I - r^r^T),
// B0_s = sum_t B_st(0), rho the SPH density and P/rho = c^2/gamma. Units: c = d = 1, so
// omega^2 is in c^2/d^2 and kappa in 1/d, in the lattice file's orientation. The mass
// cancels: the spectrum does not depend on a_p. With adaptive h (h_i = eta (m/rho_i)^(1/D)
// and the grad-h terms) the matrix gains the h-derivatives of the gradients and other
// coefficients (h_model.hpp); the equilibrium h is k d in both models.
#pragma once

#include "kernels/kernel.hpp"
#include "lattices/lattice.hpp"
#include "stability/h_model.hpp"

#include <Eigen/Core>

#include <array>
#include <complex>
#include <string>
#include <vector>

namespace sphkern {

// Checks of the inputs the command line and the Python module take alike; Error(usage)
// whose message starts with `what` (an option's name, or the option and its text).
inline constexpr double min_gamma = 1e-6, max_gamma = 1e6;
void check_gamma(double gamma, const std::string& what); // in [min_gamma, max_gamma]
Eigen::Vector3d checked_wavevector(const std::vector<double>& components, int dimension,
                                   const std::string& what); // D finite components, 0 < |kappa| <= 1e6

struct DispersionModes {
    std::vector<double> omega2;          // ascending, D * sites of them
    std::vector<Eigen::VectorXcd> modes; // unit polarisation of each (D per site)
    std::vector<double> longitudinal;    // |kappa^ . xi|^2 summed over sites: 1 longitudinal, 0 transverse
};

class Dispersion {
public:
    // Throws Error(input) for gamma <= 0, a kernel without the lattice's dimension, a neighbour
    // list over max_dispersion_neighbours (stability_budget.hpp), or a
    // multi-site lattice whose sites are not an equilibrium with one pressure (different
    // SPH densities, or a non-zero first moment at a site).
    // Adaptive h also refuses a site whose h-derivative of the first moment does not vanish.
    Dispersion(const Kernel& kernel, const Lattice& lattice, double k, double gamma, HModel h_model = HModel::fixed);

    int dimension() const { return dim_; }
    int sites() const { return static_cast<int>(neighbours_.size()); }
    int branches() const { return dim_ * sites(); }
    double k() const { return k_; }
    double gamma() const { return gamma_; }
    HModel h_model() const { return h_model_; }
    // The grad-h factor Omega = 1 + (h / (D rho)) sum_j m dW_ij/dh (1 with fixed h).
    double grad_h_factor() const { return coefficients_.omega; }
    // eta of h = eta (m / rho)^(1/D) at the equilibrium h = k d.
    double eta() const;
    // The SPH density over the reference density rho0 = m / (a_p d^D): 1 + eps_rho.
    double density_ratio() const { return density_ / mass_; }

    // The dispersion matrix (D * sites square, Hermitian; real for one site).
    Eigen::MatrixXcd matrix(const Eigen::Vector3d& kappa) const;
    // Its eigenvalues, ascending.
    std::vector<double> omega2(const Eigen::Vector3d& kappa) const;
    DispersionModes modes(const Eigen::Vector3d& kappa) const;
    // Where site s sits relative to site 0 within a cell, in units of d.
    Eigen::Vector3d site_offset(int s) const { return offsets_[static_cast<std::size_t>(s)]; }
    const Eigen::Matrix3d& basis() const { return basis_; } // the cell's vectors (columns), in units of d

    // One site only: T / kappa^2 in the long-wave limit along the unit direction n,
    // T = m sum_j H (n.x_j)^2 / 2, over rho0 (the continuum makes it n n^T). With eps_rho
    // and the gradient-error tensor E it gives the long-wave limit of the matrix:
    //   omega^2 / kappa^2 -> (1 - 2/gamma) (I + E) n n^T (I + E) / (1 + eps_rho)^2 + (2/gamma) T / (1 + eps_rho).
    Eigen::Matrix3d long_wave_stiffness(const Eigen::Vector3d& n) const;
    // One site only: the limit of the matrix over kappa^2 along n, from moments of the
    // neighbours (S ~ kappa (sum g x^T) n, T ~ kappa^2 stiffness): exact, no sin or cos.
    Eigen::Matrix3d long_wave_matrix(const Eigen::Vector3d& n) const;

private:
    struct Neighbour {
        Eigen::Vector3d x;                                    // x_j - x_i in units of d
        int site;                                             // the motif site of j
        std::array<int, 3> cell;                              // x = basis * cell + the sites' offset
        Eigen::Vector3d gradient;                             // m grad_i W(r_ij)
        Eigen::Matrix3d hessian;                              // m H(r_ij)
        Eigen::Vector3d h_gradient = Eigen::Vector3d::Zero(); // m d/dh grad_i W(r_ij) (adaptive h only)
    };
    // exp(i kappa.x) of every neighbour, as products of exp(i n kappa.a_j) over the cells'
    // integer coordinates: a few sincos per wave vector instead of one per neighbour.
    // Long waves (|kappa| < fast_phase_min) take sin and cos directly, so that
    // 1 - cos(kappa.x) keeps its digits.
    static constexpr double fast_phase_min = 0.1;
    bool fast_phases(const Eigen::Vector3d& kappa) const;
    std::vector<std::complex<double>> cell_phases(const Eigen::Vector3d& kappa) const; // per axis, from cell_min_
    std::complex<double> phase_of(const Neighbour& nb, const std::vector<std::complex<double>>& table) const;

    // The constructor's steps, in order.
    struct SiteSums {
        double density = 0, Z = 0, Z2 = 0; // Z, Z2: site 0 only, with adaptive h
        Eigen::Vector3d first = Eigen::Vector3d::Zero(), first_h = Eigen::Vector3d::Zero();
    };
    void check_inputs(const Kernel& kernel, const Lattice& lattice, double k, double gamma) const;
    void list_neighbours(const Kernel& kernel, const Lattice& lattice, int s, SiteSums& sums,
                         std::array<int, 3>& cell_max);
    Neighbour neighbour_at(const Eigen::Vector3d& x, int s, int t, const Eigen::Matrix3d& to_cells, double dw,
                           double d2w, std::array<int, 3>& cell_max);
    void check_site_at_rest(const Lattice& lattice, int s, const SiteSums& sums) const;
    void sum_long_wave_moments();
    void check_one_density(const Lattice& lattice, const std::vector<double>& densities) const;
    void set_coefficients(double Z, double Z2);

    std::vector<std::vector<Neighbour>> neighbours_; // per site
    Eigen::Matrix3d basis_;
    std::vector<Eigen::Vector3d> offsets_; // per site pair s * sites + t: x_t - x_s within a cell
    std::array<int, 3> cell_min_{}, cell_span_{};
    Eigen::Matrix3d gradient_moment_ = Eigen::Matrix3d::Zero();   // site 0: sum m grad W x^T
    Eigen::Matrix3d h_gradient_moment_ = Eigen::Matrix3d::Zero(); // site 0: sum m d/dh grad W x^T
    std::array<Eigen::Matrix3d, 9> hessian_moments_{};            // site 0: sum m H x_a x_b / 2
    bool integer_cells_ = true;
    int dim_;
    double k_, gamma_, mass_, density_;
    HModel h_model_;
    DispersionCoefficients coefficients_; // fixed h: (1 - 2/gamma)/rho^2, 0 and 2/(gamma rho)
    double c_gradient_, c_cross_, c_hessian_;
};

} // namespace sphkern
