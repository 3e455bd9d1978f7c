#include "requests/assess_particles.hpp"

#include "codes/code_table.hpp"
#include "lattices/lattice.hpp"
#include "requests/particles_report.hpp"
#include "support/error.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace sphkern {

namespace {

// The half-width of the middle 98% of a measure about zero.
double spread(const Summary& s) { return std::max(std::abs(s.p1), std::abs(s.p99)); }

// "swift eta 1.2348" or "swift's stored h".
std::string setting_text(const ParticleArguments& given)
{
    if (given.code)
        return fmt::format("{} {} {:g}", given.code->code,
                           code_profile(given.code->code, ValueSource::argument("code")).parameter, given.code->value);
    return fmt::format("{}'s stored h", *given.stored_h_code);
}

// The measured particles whose lambda_min is above (interior) or at most (surface) the bound.
ParticleRegion region(const ParticleMeasures& m, std::size_t measured, bool interior, int threads)
{
    std::vector<std::size_t> rows;
    for (std::size_t i = 0; i < measured; ++i)
        if ((m.scalars[i].lambda_min > interior_lambda) == interior) rows.push_back(i);
    ParticleRegion r;
    r.particles = rows.size();
    if (rows.empty()) return r;
    auto of = [&](auto field) {
        return summarise_values(rows.size(), threads, [&](std::size_t k) { return m.scalars[rows[k]].*field; });
    };
    r.e0 = of(&MeasureRecord::e0), r.eps_gradp = of(&MeasureRecord::eps_gradp),
    r.lambda_min = of(&MeasureRecord::lambda_min);
    return r;
}

nlohmann::json region_json(const ParticleRegion& r)
{
    if (r.particles == 0) return {{"particles", 0}};
    return {{"particles", r.particles},
            {"e0", summary_json(r.e0)},
            {"eps_gradp", summary_json(r.eps_gradp)},
            {"lambda_min", summary_json(r.lambda_min)}};
}

std::string region_text(const char* name, const ParticleRegion& r)
{
    if (r.particles == 0) return fmt::format("{}: no particle", name);
    return fmt::format(
        "{}: {} particles, e0 in [{:.3g}, {:.3g}], eps_gradp in [{:.3g}, {:.3g}] (p1 to p99), lambda_min "
        "median {:.3g}",
        name, r.particles, r.e0.p1, r.e0.p99, r.eps_gradp.p1, r.eps_gradp.p99, r.lambda_min.p50);
}

// The setting on `lattice`: the code's parameter where it was given, else the set's mean h
// over its mean spacing (h_over_l, the same resolution on every lattice).
LatticeStability lattice_stability(const Kernel& kernel, const std::string& name, const ParticleArguments& given,
                                   const ParticleAssessResult& a, const CodeProfile& code,
                                   const StabilityPressure& pressure)
{
    LatticeStability s{name, 0, {}, ""};
    const Lattice lattice = load_lattice(name);
    EpsRequest request;
    if (given.code) request.code = CodeSetting{given.code->code, given.code->value};
    else request.k = {a.answer.points.front().eta}, request.axis = Axis::eta;
    const EpsSources sources{ValueSource::argument("h_over_l"),
                             ValueSource::argument("axis"),
                             {},
                             ValueSource::argument("code"),
                             ValueSource::argument(code.parameter)};
    try {
        s.k = run_eps_at_k(request, sources, kernel, lattice).k;
        // SWIFT, Phantom and GADGET set h from the density: their h model is the adaptive one.
        s.stability = stability_at(kernel, lattice, s.k, pressure.gamma,
                                   code.from_sph_density ? HModel::adaptive : HModel::fixed, default_horizon);
    } catch (const Error& e) {
        if (e.code() != ExitCode::input && e.code() != ExitCode::usage) throw;
        s.refused = e.what();
    }
    return s;
}

std::string stable_lattices_text(const std::vector<LatticeStability>& lattices)
{
    std::vector<std::string> stable, not_stable;
    for (const auto& l : lattices)
        (l.refused.empty() && l.stability.verdict == Verdict::stable ? stable : not_stable).push_back(l.lattice);
    if (stable.empty())
        return fmt::format("unstable on every lattice of its dimension ({})", fmt::join(not_stable, ", "));
    return fmt::format("stable on {}{}; assess the setting on {} for a recommended one", fmt::join(stable, ", "),
                       not_stable.empty() ? "" : fmt::format(", not on {}", fmt::join(not_stable, ", ")),
                       stable.size() == 1 ? stable.front() : "one of them");
}

} // namespace

ParticleAssessResult assess_particles(const Kernel& kernel, const ParticleSet& set, const ParticleArguments& given,
                                      const ParticleSources& sources, double epsilon, bool with_lattices)
{
    if (!given.code && !given.stored_h_code)
        sources.code.code.fail("on a particle set, a code's setting is assessed; expected " + sources.code.code.name);
    ParticleAssessResult a;
    a.epsilon = epsilon;
    a.answer = analyse_particles(kernel, set, particle_request(given, kernel, set, sources));
    const ParticleMeasures& m = *a.answer.measures;
    a.interior = region(m, set.measured(), true, a.answer.threads);
    a.surface = region(m, set.measured(), false, a.answer.threads);
    // Judged on the interior; a set that is all surface (a thin layer) is judged whole.
    const ParticleRegion& judged = a.interior.particles > 0 ? a.interior : a.surface;
    const double rho = spread(judged.e0), gradp = spread(judged.eps_gradp);
    a.worst = std::max(rho, gradp);
    a.worst_name = rho >= gradp ? "e0" : "eps_gradp";
    const CodeProfile& code = code_profile(given.code ? given.code->code : *given.stored_h_code, sources.code.code);
    const StabilityPressure pressure =
        stability_pressure(&code, 5.0 / 3.0, std::nullopt, ValueSource::argument("coef_sound"));
    a.pressure = pressure.text;
    for (const auto& name : with_lattices ? shipped_lattice_names() : std::vector<std::string>())
        if (load_lattice(name).dimension == set.dimension)
            a.lattices.push_back(lattice_stability(kernel, name, given, a, code, pressure));
    a.verdict =
        fmt::format("{} with {} on {} ({} particles, {} interior): {} (98% of the interior's |{}| within {:.3g} {} "
                    "{:g}); {}",
                    setting_text(given), kernel.name(), set.name, set.measured(), a.interior.particles,
                    a.accurate() ? "accurate" : "inaccurate", a.worst_name, a.worst, a.accurate() ? "<=" : ">", epsilon,
                    stable_lattices_text(a.lattices));
    return a;
}

namespace {

nlohmann::json stability_json(const ParticleAssessResult& a)
{
    nlohmann::json lattices = nlohmann::json::array();
    for (const auto& l : a.lattices) {
        nlohmann::json one = {{"lattice", l.lattice}};
        if (!l.refused.empty()) one["refused"] = l.refused;
        else {
            one.update({{"k", l.k},
                        {"h_model", h_model_name(l.stability.h_model)},
                        {"verdict", verdict_name(l.stability.verdict)}});
            if (l.stability.verdict != Verdict::stable)
                one.update({{"growth_time", l.stability.growth_time}, {"mode", l.stability.mode}});
        }
        lattices.push_back(one);
    }
    return {{"pressure", a.pressure}, {"horizon", default_horizon}, {"lattices", lattices}};
}

} // namespace

nlohmann::json particle_assess_document(const Kernel& kernel, const ParticleSet& set, const ParticleArguments& given,
                                        const ParticleAssessResult& a)
{
    return {{"particles", particle_answer_json(kernel, set, a.answer, given)},
            {"interior", region_json(a.interior)},
            {"surface", region_json(a.surface)},
            {"surface_criterion", fmt::format("lambda_min(I + E) <= {:g}", interior_lambda)},
            {"condition_22",
             {{"epsilon", a.epsilon},
              {"over", "p1 to p99 of the interior's e0 and eps_gradp"},
              {"holds", a.accurate()},
              {"margin", a.epsilon - a.worst}}},
            {"stability", stability_json(a)},
            {"verdict", a.verdict}};
}

void print_particle_assess(std::FILE* out, const Kernel& kernel, const ParticleSet& set, const ParticleArguments& given,
                           const ParticleAssessResult& a)
{
    print_particle_answer(out, kernel, set, a.answer, given);
    fmt::print(out,
               "\nfree surface: lambda_min(I + E) <= {:g}, the smallest eigenvalue of the first-order correction "
               "matrix (1 inside a fluid, about 0.5 on its surface)\n{}\n{}\n",
               interior_lambda, region_text("interior", a.interior), region_text("surface", a.surface));
    fmt::print(out,
               "condition (22), epsilon = {:g}: {} for the middle 98% of the interior (margin {:.3g}: epsilon less "
               "the larger of |p1| and |p99| of e0 and eps_gradp; e0 = sum_j V_j W_ij - 1, each particle against "
               "its own density)\n",
               a.epsilon, a.accurate() ? "holds" : "fails", a.epsilon - a.worst);
    fmt::print(out, "linear stability of the same setting on each lattice ({}, horizon {:g} d/c):\n", a.pressure,
               default_horizon);
    for (const auto& l : a.lattices)
        if (l.refused.empty())
            fmt::print(out, "  {:<10} k = {:<9.5g} {} h: {}\n", l.lattice, l.k, h_model_name(l.stability.h_model),
                       stability_text(l.stability));
        else fmt::print(out, "  {:<10} not judged: {}\n", l.lattice, l.refused);
    fmt::print(out, "{}\n", a.verdict);
}

} // namespace sphkern
