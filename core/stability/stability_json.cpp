#include "stability/stability_json.hpp"

#include "analysis/hydrostatic_errors.hpp"
#include "analysis/results_json.hpp"
#include "stability/dispersion_path.hpp"
#include "stability/stability_budget.hpp"
#include "stability/stability_over_k.hpp"
#include "stability/stability_scan.hpp"
#include "stability/zone_minimum.hpp"

#include <nlohmann/json.hpp>

#include <cmath>

namespace sphkern {

namespace {

nlohmann::json vector_json(const Eigen::Vector3d& v, int dim)
{
    nlohmann::json a = nlohmann::json::array();
    for (int i = 0; i < dim; ++i) a.push_back(v[i] == 0 ? 0.0 : v[i]); // no "-0"
    return a;
}

nlohmann::json header(const Kernel& kernel, const Lattice& lattice, double k, double gamma, HModel h_model)
{
    return {{"kernel", kernel.label()},
            {"lattice", lattice.name},
            {"k", k},
            {"gamma", gamma},
            {"h_model", h_model_name(h_model)},
            {"second_derivative", kernel.provides_second_derivative() ? "plugin" : "numerical"}};
}

// The header at one k, with eta of h = eta (m / rho)^(1/D) and the grad-h factor for adaptive h.
nlohmann::json header(const Kernel& kernel, const Lattice& lattice, const Dispersion& dispersion)
{
    auto document = header(kernel, lattice, dispersion.k(), dispersion.gamma(), dispersion.h_model());
    if (dispersion.h_model() == HModel::adaptive) {
        document["h_over_l"] = dispersion.eta();
        document["grad_h_factor"] = dispersion.grad_h_factor();
    }
    return document;
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

nlohmann::json zone_scan_json(const StabilityScan& scan)
{
    return {{"grid", scan.grid},
            {"grids", scan.levels},
            {"converged", scan.converged},
            {"change", scan.change},
            {"tolerance", {{"absolute", zone_tolerance_absolute}, {"relative", zone_tolerance_relative}}}};
}

} // namespace

nlohmann::json mode_json(const ModeCharacter& mode, int dim)
{
    return {{"kind", mode_kind_name(mode.kind)},
            {"unfolded_wavevector", vector_json(mode.unfolded, dim)},
            {"in_phase", mode.in_phase},
            {"longitudinal", mode.longitudinal}};
}

nlohmann::json stability_sample_json(const StabilitySample& s, int dim)
{
    nlohmann::json entry = {{"k", s.k},
                            {"min_omega2", s.branch_minima.front()},
                            {"stable", s.stable},
                            {"verdict", verdict_name(s.verdict)},
                            {"longitudinal", s.longitudinal},
                            {"branch_minima", s.branch_minima}};
    if (std::isfinite(s.floor)) entry["valley_floor"] = s.floor;
    if (std::isfinite(s.growth_time)) {
        entry["growth_time"] = s.growth_time;
        entry["at"] = vector_json(s.at, dim);
        entry["mode"] = mode_json(s.mode, dim);
    }
    return entry;
}

nlohmann::json dispersion_document(const Kernel& kernel, const Lattice& lattice, double k, double gamma,
                                   const Eigen::Vector3d& kappa, HModel h_model)
{
    const Dispersion dispersion(kernel, lattice, k, gamma, h_model);
    const auto modes = dispersion.modes(kappa);
    const int D = lattice.dimension;
    auto document = header(kernel, lattice, dispersion);
    document["wavevector"] = vector_json(kappa, D);
    document["omega2"] = modes.omega2;
    nlohmann::json list = nlohmann::json::array();
    int most = 0;
    for (int b = 0; b < dispersion.branches(); ++b) {
        nlohmann::json polarisation = nlohmann::json::array();
        for (Eigen::Index i = 0; i < modes.modes[b].size(); ++i)
            polarisation.push_back({modes.modes[b][i].real(), modes.modes[b][i].imag()});
        list.push_back(
            {{"omega2", modes.omega2[b]}, {"longitudinal", modes.longitudinal[b]}, {"polarisation", polarisation}});
        if (modes.longitudinal[b] > modes.longitudinal[most]) most = b;
    }
    document["modes"] = list;
    document["longitudinal_mode"] = most;
    return document;
}

nlohmann::json stability_document(const Kernel& kernel, const Lattice& lattice, double k, double gamma, int grid,
                                  int threads, double horizon, HModel h_model)
{
    check_stability_work("the stability zone scan", kernel, lattice, k, k, 0, grid);
    const Dispersion dispersion(kernel, lattice, k, gamma, h_model);
    const auto reciprocal = reciprocal_lattice(lattice);
    const auto scan = scan_brillouin_zone(dispersion, reciprocal, grid, threads);
    const int D = lattice.dimension;
    auto document = header(kernel, lattice, dispersion);
    document["bravais"] = reciprocal.bravais;
    nlohmann::json b = nlohmann::json::array();
    for (int i = 0; i < D; ++i) b.push_back(vector_json(reciprocal.vectors.col(i), D));
    document["reciprocal_vectors"] = b;
    document["grid_points"] = scan.grid_points;
    document["zone_scan"] = zone_scan_json(scan);
    document["stable"] = scan.stable;
    document["horizon"] = horizon;
    document["verdict"] = verdict_name(scan.verdict(horizon));
    if (std::isfinite(scan.growth_time())) document["growth_time"] = scan.growth_time();
    document["min_omega2"] = scan.lowest().omega2;
    document["at"] = vector_json(scan.lowest().kappa, D);
    document["branch"] = scan.lowest().branch;
    document["longitudinal"] = scan.lowest().longitudinal;
    document["mode"] = mode_json(scan.mode, D);
    nlohmann::json branches = nlohmann::json::array();
    for (const auto& m : scan.minima)
        branches.push_back({{"branch", m.branch},
                            {"min_omega2", m.omega2},
                            {"at", vector_json(m.kappa, D)},
                            {"longitudinal", m.longitudinal}});
    document["branches"] = branches;
    document["long_wave"] = {{"min_omega2_over_kappa2", scan.long_wave.omega2_over_kappa2},
                             {"direction", vector_json(scan.long_wave.direction, D)}};
    // Long waves: the speed per direction, and for one site how it follows from the
    // hydrostatic errors (eps_rho, E) and the stiffness term (fixed h: the relation of the
    // method document holds for it only).
    std::unique_ptr<HydrostaticErrors> errors;
    if (dispersion.sites() == 1 && h_model == HModel::fixed)
        errors = std::make_unique<HydrostaticErrors>(kernel, lattice, 0, lattice.volume_per_site(), lattice.gravity, k);
    nlohmann::json speeds = nlohmann::json::array();
    for (const auto& [label, n] : symmetry_directions(reciprocal)) {
        const auto s = long_wave_sound_speed(dispersion, n);
        nlohmann::json entry = {{"direction", label},
                                {"unit_vector", vector_json(n, D)},
                                {"speeds", s.speeds},
                                {"longitudinal_error", s.longitudinal - 1}};
        if (errors) {
            const double eps_rho = errors->at(k).eps_rho;
            const double eps_gradp = n.dot(errors->tensor(k).tensor * n);
            const double stiffness = n.dot(dispersion.long_wave_stiffness(n) * n);
            entry["eps_rho"] = eps_rho;
            entry["eps_gradp"] = eps_gradp;
            entry["pressure_term"] = (1 + eps_gradp) / (1 + eps_rho) - 1;
            entry["stiffness_term"] = stiffness / (1 + eps_rho) - 1;
        }
        speeds.push_back(entry);
    }
    document["sound_speed"] = speeds;
    return document;
}

nlohmann::json stability_over_k_document(const Kernel& kernel, const Lattice& lattice, double k_min, double k_max,
                                         int steps, double gamma, int grid, int threads, double horizon, HModel h_model)
{
    const auto scan = stability_over_k(kernel, lattice, k_min, k_max, steps, gamma, grid, threads, horizon, h_model);
    auto document = header(kernel, lattice, k_min, gamma, h_model);
    document.erase("k");
    document["k_range"] = {k_min, k_max};
    document["bravais"] = scan.bravais;
    document["horizon"] = horizon;
    nlohmann::json samples = nlohmann::json::array(), between = nlohmann::json::array();
    for (const auto& s : scan.samples) samples.push_back(stability_sample_json(s, lattice.dimension));
    for (const auto& s : scan.between) between.push_back(stability_sample_json(s, lattice.dimension));
    document["samples"] = samples;
    document["between"] = between;
    document["stable_intervals"] = intervals_json(scan.stable);
    document["stable_at_horizon"] = intervals_json(scan.usable);
    return document;
}

nlohmann::json dispersion_path_json(const DispersionPath& path)
{
    nlohmann::json points = nlohmann::json::array();
    for (std::size_t i = 0; i < path.labels.size(); ++i)
        points.push_back({{"label", path.labels[i]}, {"at", path.label_positions[i]}});
    return {{"points", points}, {"position", path.position}, {"omega2", path.omega2}};
}

nlohmann::json dispersion_path_document(const Kernel& kernel, const Lattice& lattice, double k, double gamma,
                                        int points, HModel h_model)
{
    check_dispersion_work("the dispersion path", kernel, lattice, k, points);
    const Dispersion dispersion(kernel, lattice, k, gamma, h_model);
    const auto reciprocal = reciprocal_lattice(lattice);
    auto document = header(kernel, lattice, dispersion);
    document["bravais"] = reciprocal.bravais;
    document["path"] = dispersion_path_json(dispersion_along_path(dispersion, reciprocal, points));
    return document;
}

} // namespace sphkern
