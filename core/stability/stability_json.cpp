#include "stability/stability_json.hpp"

#include "analysis/results_json.hpp"
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

nlohmann::json header(const StabilitySetting& s)
{
    nlohmann::json document = {{"kernel", s.kernel},
                               {"lattice", s.lattice},
                               {"k", s.k},
                               {"gamma", s.gamma},
                               {"h_model", h_model_name(s.h_model)},
                               {"second_derivative", s.plugin_second_derivative ? "plugin" : "numerical"}};
    if (s.eta) document["h_over_l"] = *s.eta;
    if (s.grad_h_factor) document["grad_h_factor"] = *s.grad_h_factor;
    return document;
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

nlohmann::json stability_json(const WavevectorModes& result)
{
    const DispersionModes& modes = result.modes;
    auto document = header(result.setting);
    document["wavevector"] = vector_json(result.kappa, result.setting.dimension);
    document["omega2"] = modes.omega2;
    nlohmann::json list = nlohmann::json::array();
    for (std::size_t b = 0; b < modes.omega2.size(); ++b) {
        nlohmann::json polarisation = nlohmann::json::array();
        for (Eigen::Index i = 0; i < modes.modes[b].size(); ++i)
            polarisation.push_back({modes.modes[b][i].real(), modes.modes[b][i].imag()});
        list.push_back(
            {{"omega2", modes.omega2[b]}, {"longitudinal", modes.longitudinal[b]}, {"polarisation", polarisation}});
    }
    document["modes"] = list;
    document["longitudinal_mode"] = result.longitudinal_mode;
    return document;
}

nlohmann::json stability_json(const ZoneScan& result)
{
    const StabilityScan& scan = result.scan;
    const int D = result.setting.dimension;
    auto document = header(result.setting);
    document["bravais"] = result.reciprocal.bravais;
    nlohmann::json b = nlohmann::json::array();
    for (int i = 0; i < D; ++i) b.push_back(vector_json(result.reciprocal.vectors.col(i), D));
    document["reciprocal_vectors"] = b;
    document["grid_points"] = scan.grid_points;
    document["zone_scan"] = zone_scan_json(scan);
    document["stable"] = scan.stable;
    document["horizon"] = result.horizon;
    document["verdict"] = verdict_name(scan.verdict(result.horizon));
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
    nlohmann::json speeds = nlohmann::json::array();
    for (const DirectionSpeed& s : result.speeds) {
        nlohmann::json entry = {{"direction", s.direction},
                                {"unit_vector", vector_json(s.unit, D)},
                                {"speeds", s.speed.speeds},
                                {"longitudinal_error", s.speed.longitudinal - 1}};
        if (s.terms) {
            entry["eps_rho"] = s.terms->eps_rho;
            entry["eps_gradp"] = s.terms->eps_gradp;
            entry["pressure_term"] = s.terms->pressure_term;
            entry["stiffness_term"] = s.terms->stiffness_term;
        }
        speeds.push_back(entry);
    }
    document["sound_speed"] = speeds;
    return document;
}

nlohmann::json stability_json(const StabilityAgainstK& result)
{
    const StabilityOverK& scan = result.scan;
    const int D = result.setting.dimension;
    auto document = header(result.setting);
    document.erase("k");
    document["k_range"] = {result.setting.k, result.k_max};
    document["bravais"] = scan.bravais;
    document["horizon"] = scan.horizon;
    nlohmann::json samples = nlohmann::json::array(), between = nlohmann::json::array();
    for (const auto& s : scan.samples) samples.push_back(stability_sample_json(s, D));
    for (const auto& s : scan.between) between.push_back(stability_sample_json(s, D));
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

nlohmann::json stability_json(const PathDispersion& result)
{
    auto document = header(result.setting);
    document["bravais"] = result.bravais;
    document["path"] = dispersion_path_json(result.path);
    return document;
}

} // namespace sphkern
