#include "requests/assess_particles.hpp"

#include "codes/code_table.hpp"
#include "requests/particles_report.hpp"

#include <fmt/format.h>
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
    auto of = [&](auto field) { return summarise_values(rows.size(), threads, [&](std::size_t k) { return m.scalars[rows[k]].*field; }); };
    r.e0 = of(&MeasureRecord::e0), r.eps_gradp = of(&MeasureRecord::eps_gradp), r.lambda_min = of(&MeasureRecord::lambda_min);
    return r;
}

nlohmann::json region_json(const ParticleRegion& r)
{
    if (r.particles == 0) return {{"particles", 0}};
    return {{"particles", r.particles}, {"e0", summary_json(r.e0)}, {"eps_gradp", summary_json(r.eps_gradp)},
            {"lambda_min", summary_json(r.lambda_min)}};
}

std::string region_text(const char* name, const ParticleRegion& r)
{
    if (r.particles == 0) return fmt::format("{}: no particle", name);
    return fmt::format("{}: {} particles, e0 in [{:.3g}, {:.3g}], eps_gradp in [{:.3g}, {:.3g}] (p1 to p99), lambda_min "
                       "median {:.3g}",
                       name, r.particles, r.e0.p1, r.e0.p99, r.eps_gradp.p1, r.eps_gradp.p99, r.lambda_min.p50);
}

const char* lattices_of(int dimension) { return dimension == 2 ? "triangular or square" : "fcc, bcc or sc"; }

} // namespace

ParticleAssessResult assess_particles(const Kernel& kernel, const ParticleSet& set, const ParticleArguments& given,
                                      const ParticleSources& sources, double epsilon)
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
    a.verdict = fmt::format("{} with {} on {} ({} particles, {} interior): {} (98% of the interior's |{}| within {:.3g} {} "
                            "{:g}); stability and a recommended setting need a lattice: assess the setting on the {} "
                            "lattice",
                            setting_text(given), kernel.name(), set.name, set.measured(), a.interior.particles,
                            a.accurate() ? "accurate" : "inaccurate", a.worst_name, a.worst, a.accurate() ? "<=" : ">",
                            epsilon, lattices_of(set.dimension));
    return a;
}

nlohmann::json particle_assess_document(const Kernel& kernel, const ParticleSet& set, const ParticleArguments& given,
                                        const ParticleAssessResult& a)
{
    return {{"particles", particle_answer_json(kernel, set, a.answer, given)},
            {"interior", region_json(a.interior)},
            {"surface", region_json(a.surface)},
            {"surface_criterion", fmt::format("lambda_min(I + E) <= {:g}", interior_lambda)},
            {"condition_22",
             {{"epsilon", a.epsilon}, {"over", "p1 to p99 of the interior's e0 and eps_gradp"}, {"holds", a.accurate()},
              {"margin", a.epsilon - a.worst}}},
            {"stability", nullptr},
            {"verdict", a.verdict}};
}

void print_particle_assess(std::FILE* out, const Kernel& kernel, const ParticleSet& set, const ParticleArguments& given,
                           const ParticleAssessResult& a)
{
    print_particle_answer(out, kernel, set, a.answer, given);
    fmt::print(out, "\nfree surface: lambda_min(I + E) <= {:g}, the smallest eigenvalue of the first-order correction "
                    "matrix (1 inside a fluid, about 0.5 on its surface)\n{}\n{}\n",
               interior_lambda, region_text("interior", a.interior), region_text("surface", a.surface));
    fmt::print(out, "condition (22), epsilon = {:g}: {} for the middle 98% of the interior (margin {:.3g}: epsilon less "
                    "the larger of |p1| and |p99| of e0 and eps_gradp; e0 = sum_j V_j W_ij - 1, each particle against "
                    "its own density)\n",
               a.epsilon, a.accurate() ? "holds" : "fails", a.epsilon - a.worst);
    fmt::print(out, "{}\n", a.verdict);
}

} // namespace sphkern
