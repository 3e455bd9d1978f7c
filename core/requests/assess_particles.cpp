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

} // namespace

ParticleAssessResult assess_particles(const Kernel& kernel, const ParticleSet& set, const ParticleArguments& given,
                                      const ParticleSources& sources, double epsilon)
{
    if (!given.code && !given.stored_h_code)
        sources.code.code.fail("on a particle set, a code's setting is assessed; expected " + sources.code.code.name);
    ParticleAssessResult a;
    a.epsilon = epsilon;
    a.answer = analyse_particles(kernel, set, particle_request(given, kernel, set, sources));
    const auto& point = a.answer.points.front();
    const double rho = spread(point.statistic("eps_rho")), gradp = spread(point.statistic("eps_gradp"));
    a.worst = std::max(rho, gradp);
    a.worst_name = rho >= gradp ? "eps_rho" : "eps_gradP";
    a.verdict = fmt::format("{} with {} on {} ({} particles): {} (98% of |{}| within {:.3g} {} {:g}); stability and a "
                            "recommended setting need a lattice: assess it on the lattice nearest the set",
                            setting_text(given), kernel.name(), set.name, set.measured(),
                            a.accurate() ? "accurate" : "inaccurate", a.worst_name, a.worst,
                            a.accurate() ? "<=" : ">", epsilon);
    return a;
}

nlohmann::json particle_assess_document(const Kernel& kernel, const ParticleSet& set, const ParticleArguments& given,
                                        const ParticleAssessResult& a)
{
    return {{"particles", particle_answer_json(kernel, set, a.answer, given)},
            {"condition_22",
             {{"epsilon", a.epsilon}, {"over", "p1 to p99"}, {"holds", a.accurate()}, {"margin", a.epsilon - a.worst}}},
            {"stability", nullptr},
            {"verdict", a.verdict}};
}

void print_particle_assess(std::FILE* out, const Kernel& kernel, const ParticleSet& set, const ParticleArguments& given,
                           const ParticleAssessResult& a)
{
    print_particle_answer(out, kernel, set, a.answer, given);
    fmt::print(out, "condition (22), epsilon = {:g}: {} for the middle 98% of the particles (margin {:.3g}: epsilon less "
                    "the larger of |p1| and |p99| of eps_rho and eps_gradp)\n",
               a.epsilon, a.accurate() ? "holds" : "fails", a.epsilon - a.worst);
    fmt::print(out, "{}\n", a.verdict);
}

} // namespace sphkern
