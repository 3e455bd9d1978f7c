#include "requests/assess_sweep.hpp"

#include "codes/code_table.hpp"
#include "requests/particles_report.hpp"
#include "support/error.hpp"
#include "support/process/progress.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>

namespace sphkern {

CodeSweepResult sweep_code_setting(const Kernel& kernel, const ParticleSet& set, ParticleArguments given,
                                   const ParticleSources& sources, double epsilon, double from, double to, int steps,
                                   const ValueSource& range, const ValueSource& steps_source)
{
    if (!given.code) sources.code.code.fail("a sweep takes the code's parameter; expected " + sources.code.code.name);
    check_number(from, 0, 1e6, LowEnd::open, range);
    check_number(to, 0, 1e6, LowEnd::open, range);
    if (!(to > from)) range.fail(fmt::format("[{}, {}]: expected min < max", from, to));
    check_range(steps, 1, 100, steps_source);
    CodeSweepResult r;
    r.code = given.code->code;
    r.parameter = code_profile(r.code, sources.code.code).parameter;
    r.epsilon = epsilon;
    Progress progress(fmt::format("{} values of {}", steps + 1, r.parameter), static_cast<std::size_t>(steps) + 1);
    for (int s = 0; s <= steps; ++s) {
        const double value = from + (to - from) * s / steps;
        given.code->value = value;
        const ParticleAssessResult a = assess_particles(kernel, set, given, sources, epsilon, false);
        r.points.push_back(
            {value, a.answer.points.front().mean_neighbours, a.interior, epsilon - a.worst, a.accurate()});
        if (a.accurate() && !r.needed) r.needed = value;
        progress.step(fmt::format("{} {:g}", r.parameter, value));
    }
    if (!r.needed) {
        const auto best =
            std::max_element(r.points.begin(), r.points.end(),
                             [](const SweepPoint& a, const SweepPoint& b) { return a.margin < b.margin; });
        range.fail(
            fmt::format("[{:g}, {:g}]: condition (22), epsilon {:g}, holds on the interior of {} for no {} {} in it "
                        "(the nearest, {:g}, misses by {:.3g}); expected a range where it holds",
                        from, to, epsilon, set.name, r.code, r.parameter, best->value, -best->margin));
    }
    return r;
}

nlohmann::json code_sweep_json(const CodeSweepResult& r)
{
    nlohmann::json points = nlohmann::json::array();
    for (const auto& p : r.points)
        points.push_back({{"value", p.value},
                          {"mean_neighbours", p.mean_neighbours},
                          {"interior",
                           {{"particles", p.interior.particles},
                            {"e0", summary_json(p.interior.e0)},
                            {"eps_gradp", summary_json(p.interior.eps_gradp)}}},
                          {"margin", p.margin},
                          {"holds", p.holds}});
    return {{"code", r.code},
            {"parameter", r.parameter},
            {"epsilon", r.epsilon},
            {"points", points},
            {"needed", *r.needed}};
}

void print_code_sweep(std::FILE* out, const Kernel& kernel, const ParticleSet& set, const CodeSweepResult& r)
{
    fmt::print(out, "{} with {} on {}: condition (22), epsilon {:g}, on the interior at each {}\n\n", r.code,
               kernel.name(), set.name, r.epsilon, r.parameter);
    fmt::print(out, "{:>10} {:>10} {:>9} {:>11} {:>11} {:>11} {:>11} {:>10}  {}\n", r.parameter, "neighbours",
               "interior", "e0 p1", "e0 p99", "gradp p1", "gradp p99", "margin", "(22)");
    for (const auto& p : r.points)
        fmt::print(out, "{:>10.6g} {:>10.2f} {:>9} {:>11.3e} {:>11.3e} {:>11.3e} {:>11.3e} {:>10.3g}  {}\n", p.value,
                   p.mean_neighbours, p.interior.particles, p.interior.e0.p1, p.interior.e0.p99,
                   p.interior.eps_gradp.p1, p.interior.eps_gradp.p99, p.margin, p.holds ? "holds" : "fails");
    fmt::print(out,
               "\nthis set needs {} {} {:g}: the smallest value of the sweep at which condition (22) holds on its "
               "interior (the sweep's step {:g})\n",
               r.code, r.parameter, *r.needed, r.points.size() > 1 ? r.points[1].value - r.points[0].value : 0.0);
}

} // namespace sphkern
