#include "stability/stability_results.hpp"

#include "analysis/hydrostatic_errors.hpp"
#include "stability/stability_budget.hpp"

#include <cmath>
#include <memory>

namespace sphkern {

namespace {

StabilitySetting setting_of(const Kernel& kernel, const Lattice& lattice, double k, double gamma, HModel h_model)
{
    return {kernel.label(), lattice.name, lattice.dimension, k, gamma, h_model, kernel.provides_second_derivative(),
            std::nullopt,   std::nullopt};
}

StabilitySetting setting_of(const Kernel& kernel, const Lattice& lattice, const Dispersion& dispersion)
{
    StabilitySetting s = setting_of(kernel, lattice, dispersion.k(), dispersion.gamma(), dispersion.h_model());
    if (dispersion.h_model() == HModel::adaptive)
        s.eta = dispersion.eta(), s.grad_h_factor = dispersion.grad_h_factor();
    return s;
}

// The directions of the high-symmetry points (Γ-X, Γ-L, ...), each once.
std::vector<std::pair<std::string, Eigen::Vector3d>> symmetry_directions(const ReciprocalLattice& reciprocal)
{
    std::vector<std::pair<std::string, Eigen::Vector3d>> directions;
    for (const auto& p : high_symmetry_path(reciprocal)) {
        if (p.kappa.norm() < 1e-12) continue;
        const Eigen::Vector3d n = p.kappa.normalized();
        bool seen = false;
        for (const auto& d : directions) seen |= std::abs(std::abs(d.second.dot(n)) - 1) < 1e-9;
        if (!seen) directions.emplace_back("Γ-" + p.label, n);
    }
    return directions;
}

} // namespace

WavevectorModes modes_at(const Kernel& kernel, const Lattice& lattice, double k, double gamma,
                         const Eigen::Vector3d& kappa, HModel h_model)
{
    const Dispersion dispersion(kernel, lattice, k, gamma, h_model);
    WavevectorModes out{setting_of(kernel, lattice, dispersion), kappa, dispersion.modes(kappa), 0};
    for (int b = 0; b < dispersion.branches(); ++b)
        if (out.modes.longitudinal[b] > out.modes.longitudinal[out.longitudinal_mode]) out.longitudinal_mode = b;
    return out;
}

ZoneScan zone_scan(const Kernel& kernel, const Lattice& lattice, double k, double gamma, int grid, int threads,
                   double horizon, HModel h_model)
{
    check_stability_work("the stability zone scan", kernel, lattice, k, k, 0, grid);
    const Dispersion dispersion(kernel, lattice, k, gamma, h_model);
    ZoneScan out{setting_of(kernel, lattice, dispersion), reciprocal_lattice(lattice), {}, horizon, {}};
    out.scan = scan_brillouin_zone(dispersion, out.reciprocal, grid, threads);
    // Long waves: the speed per direction, and for one site how it follows from the
    // hydrostatic errors (eps_rho, E) and the stiffness term (fixed h: the relation of the
    // method document holds for it only).
    std::unique_ptr<HydrostaticErrors> errors;
    if (dispersion.sites() == 1 && h_model == HModel::fixed)
        errors = std::make_unique<HydrostaticErrors>(kernel, lattice, 0, lattice.volume_per_site(), lattice.gravity, k);
    for (const auto& [label, n] : symmetry_directions(out.reciprocal)) {
        DirectionSpeed entry{label, n, long_wave_sound_speed(dispersion, n), std::nullopt};
        if (errors) {
            const double eps_rho = errors->at(k).eps_rho;
            const double eps_gradp = n.dot(errors->tensor(k).tensor * n);
            const double stiffness = n.dot(dispersion.long_wave_stiffness(n) * n);
            entry.terms = DirectionSpeed::Terms{eps_rho, eps_gradp, (1 + eps_gradp) / (1 + eps_rho) - 1,
                                                stiffness / (1 + eps_rho) - 1};
        }
        out.speeds.push_back(entry);
    }
    return out;
}

StabilityAgainstK stability_against_k(const Kernel& kernel, const Lattice& lattice, double k_min, double k_max,
                                      int steps, double gamma, int grid, int threads, double horizon, HModel h_model)
{
    return {setting_of(kernel, lattice, k_min, gamma, h_model), k_max,
            stability_over_k(kernel, lattice, k_min, k_max, steps, gamma, grid, threads, horizon, h_model)};
}

PathDispersion path_dispersion(const Kernel& kernel, const Lattice& lattice, double k, double gamma, int points,
                               HModel h_model)
{
    check_dispersion_work("the dispersion path", kernel, lattice, k, points);
    const Dispersion dispersion(kernel, lattice, k, gamma, h_model);
    const auto reciprocal = reciprocal_lattice(lattice);
    return {setting_of(kernel, lattice, dispersion), reciprocal.bravais,
            dispersion_along_path(dispersion, reciprocal, points)};
}

} // namespace sphkern
