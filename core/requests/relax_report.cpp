#include "requests/relax_report.hpp"

#include "requests/particles_report.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>

namespace sphkern {

namespace {

nlohmann::json step_json(const RelaxStep& s)
{
    return {{"step", s.step},     {"time", s.time},     {"rms_move", s.rms_move}, {"max_move", s.max_move},
            {"rms_e0", s.rms_e0}, {"rms_e1", s.rms_e1}, {"kinetic", s.kinetic}};
}

nlohmann::json settings_json(const RelaxSettings& s, const RelaxResult& run)
{
    nlohmann::json j = {{"method", relax_method_name(s.method)}, {"steps", s.steps}, {"tolerance", s.tolerance}};
    if (s.method == RelaxMethod::pressure)
        j.update({{"gamma", s.gamma}, {"dt_over_h", s.time_step}, {"dt", run.dt}, {"damping", s.damping}});
    else j.update({{"alpha", s.alpha}, {"max_move", s.max_move}});
    return j;
}

// Infinite growth times (a stable k) are written as null: JSON has no infinity.
nlohmann::json finite_or_null(double value)
{
    return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

} // namespace

nlohmann::json relax_json(const Kernel& kernel, const RelaxSettings& settings, const RelaxResult& run,
                          const RelaxedSet& judged)
{
    nlohmann::json history = nlohmann::json::array();
    for (const auto& s : run.history) history.push_back(step_json(s));
    nlohmann::json rdf = {{"bin_width", judged.quality.rdf.bin_width},
                          {"r", judged.quality.rdf.r},
                          {"g", judged.quality.rdf.g},
                          {"peak", judged.quality.rdf.peak},
                          {"peak_r", judged.quality.rdf.peak_r}};
    const auto& nh = judged.quality.nearest_histogram;
    nlohmann::json quality = {{"rdf", rdf},
                              {"nearest", summary_json(judged.quality.nearest)},
                              {"nearest_histogram", {{"min", nh.lo}, {"max", nh.hi}, {"counts", nh.counts}}},
                              {"paired", judged.quality.paired}};
    const double rms_e0 = judged.measures.points.front().statistic("e0").rms;
    return {
        {"kernel", kernel.label()},
        {"support", kernel.support()},
        {"source",
         {{"name", run.state.set.name}, {"particles", run.state.set.size()}, {"dimension", run.state.set.dimension}}},
        {"settings", settings_json(settings, run)},
        {"spacing", run.spacing},
        {"h", run.h},
        {"h_over_l", judged.eta},
        {"nh", judged.nh},
        {"steps_taken", run.history.size() - 1},
        {"stop", run.stop},
        {"history", history},
        {"final", point_json(judged.measures.points.front())},
        {"glass", quality},
        {"poisson_rms_e0", judged.poisson_rms_e0},
        {"rms_e0_over_poisson", rms_e0 / judged.poisson_rms_e0},
        {"phases", phases_json(run.phases)}};
}

void print_relax(std::FILE* out, const Kernel& kernel, const RelaxSettings& settings, const RelaxResult& run,
                 const RelaxedSet& judged)
{
    const auto& set = run.state.set;
    fmt::print(out, "{} on {}: {} particles in {}D, h = {:.6g} (h/l = {:.4f}, N_H = {:.2f}), method {}", kernel.label(),
               set.name, set.size(), set.dimension, run.h, judged.eta, judged.nh, relax_method_name(settings.method));
    if (settings.method == RelaxMethod::pressure)
        fmt::print(out, " (gamma {:.4g}, dt {:.4g} d/c, damping {:.4g} c/h)\n", settings.gamma, run.dt,
                   settings.damping);
    else fmt::print(out, " (alpha {:.4g}, at most {:.4g} h a step)\n", settings.alpha, settings.max_move);
    const RelaxStep &first = run.history.front(), &last = run.history.back();
    fmt::print(out, "stopped after {} steps ({}): RMS move of the last step {:.3e} h\n", last.step,
               run.stop == "tolerance" ? fmt::format("RMS move below --tolerance {:g} h", settings.tolerance)
                                       : std::string("--steps reached"),
               last.rms_move);
    fmt::print(out, "{:>12} {:>12} {:>12}\n", "", "start", "end");
    fmt::print(out, "{:>12} {:>12.4e} {:>12.4e}\n", "RMS e0", first.rms_e0, last.rms_e0);
    fmt::print(out, "{:>12} {:>12.4e} {:>12.4e}\n", "RMS |e1|", first.rms_e1, last.rms_e1);
    const auto& final_point = judged.measures.points.front();
    fmt::print(out, "the set made: RMS e0 {:.4e} ({:.3g} of a Poisson set's {:.4e} at this h), RMS eps_gradp {:.4e}\n",
               final_point.statistic("e0").rms, final_point.statistic("e0").rms / judged.poisson_rms_e0,
               judged.poisson_rms_e0, final_point.statistic("eps_gradp").rms);
    const auto& q = judged.quality;
    fmt::print(out,
               "g(r): highest {:.3f} at r = {:.3f} l; nearest neighbour {:.3f} l (min {:.3f}, p1 {:.3f}); "
               "paired (nearest < 0.5 l): {:.4f}\n",
               q.rdf.peak, q.rdf.peak_r, q.nearest.mean, q.nearest.min, q.nearest.p1, q.paired);
}

void write_relax_history_csv(std::ostream& out, const std::vector<RelaxStep>& history)
{
    out << "step,time,rms_move,max_move,rms_e0,rms_e1,kinetic\n";
    for (const auto& s : history)
        out << fmt::format("{},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g}\n", s.step, s.time, s.rms_move,
                           s.max_move, s.rms_e0, s.rms_e1, s.kinetic);
}

nlohmann::json pairing_json(const Kernel& kernel, const Lattice& lattice, const PairingRequest& request,
                            const std::vector<PairingPoint>& points, const std::optional<CodeK>& code)
{
    nlohmann::json rows = nlohmann::json::array();
    for (const auto& p : points)
        rows.push_back({{"k", p.k},
                        {"cells", p.cells},
                        {"particles", p.particles},
                        {"verdict", verdict_name(p.verdict)},
                        {"omega2", p.omega2},
                        {"growth_time", finite_or_null(p.growth_time)},
                        {"kind", p.kind},
                        {"predicted_rate", p.predicted_rate},
                        {"predicted_factor", p.predicted_factor},
                        {"measured_rate", p.measured_rate},
                        {"rms_start", p.rms_start},
                        {"rms_end", p.rms_end},
                        {"rms_max", p.rms_max},
                        {"paired_start", p.paired_start},
                        {"paired_end", p.paired_end},
                        {"expected", p.expected},
                        {"outcome", p.outcome},
                        {"agrees", p.agrees}});
    nlohmann::json document = {{"kernel", kernel.label()},   {"lattice", lattice.name},
                               {"noise", request.noise},     {"duration", request.duration},
                               {"damping", request.damping}, {"dt_over_h", request.time_step},
                               {"gamma", request.gamma},     {"horizon", request.horizon},
                               {"seed", request.seed},       {"points", rows}};
    if (code) document["code"] = code_k_json(*code);
    return document;
}

void print_pairing(std::FILE* out, const Kernel& kernel, const Lattice& lattice, const PairingRequest& request,
                   const std::vector<PairingPoint>& points, const std::optional<CodeK>& code)
{
    const std::string setting = code ? fmt::format(" ({} {} = {:.10g}: k = {:.10g})", code->setting.code,
                                                   code->parameter, code->setting.value, code->k)
                                     : "";
    fmt::print(out, "{} on {}{}: noise {:g} d, {:g} d/c of motion, damping {:g} c/h, gamma {:.4g}\n", kernel.label(),
               lattice.name, setting, request.noise, request.duration, request.damping, request.gamma);
    fmt::print(out, "{:>8} {:>9} {:>10} {:>12} {:>12} {:>10} {:>10} {:>11} {:>10} {:>8} {:>9} {:>9} {:>6}\n", "k",
               "verdict", "tau [d/c]", "kind", "block omega2", "rate lin.", "measured", "rms/0 lin.", "measured",
               "paired", "expected", "outcome", "agree");
    int agreeing = 0;
    for (const auto& p : points) {
        agreeing += p.agrees;
        fmt::print(out,
                   "{:>8.4f} {:>9} {:>10} {:>12} {:>12.4e} {:>10.4f} {:>10.4f} {:>11.3g} {:>10.3g} {:>8.4f} {:>9} "
                   "{:>9} {:>6}\n",
                   p.k, verdict_name(p.verdict),
                   std::isfinite(p.growth_time) ? fmt::format("{:.3g}", p.growth_time) : "-",
                   p.kind.empty() ? "-" : p.kind, p.omega2, p.predicted_rate, p.measured_rate, p.predicted_factor,
                   p.rms_end / p.rms_start, p.paired_end, p.expected, p.outcome, p.agrees ? "yes" : "NO");
    }
    fmt::print(out,
               "{} of {} k agree. Rule: from the linear RMS displacement at the end (every mode of the block "
               "damped or grown from the noise): past 0.1 d the particles must pair (a longitudinal mode) or grow; "
               "grown 10x, they must grow; at most halved, they must return (halve); between, nothing is judged.\n",
               agreeing, points.size());
}

} // namespace sphkern
