#include "relax/relax_settings.hpp"

#include "support/error.hpp"

#include <fmt/format.h>

#include <cmath>

namespace sphkern {

RelaxMethod parse_relax_method(const std::string& name)
{
    if (name == "pressure") return RelaxMethod::pressure;
    if (name == "shift") return RelaxMethod::shift;
    throw Error(ExitCode::usage, "--method " + name + ": expected pressure or shift");
}

const char* relax_method_name(RelaxMethod method) { return method == RelaxMethod::pressure ? "pressure" : "shift"; }

namespace {

void require_range(double value, double lo, double hi, bool open_lo, const char* option, const char* unit)
{
    const bool above = open_lo ? value > lo : value >= lo;
    if (!std::isfinite(value) || !above || value > hi)
        fail_usage(fmt::format("{} {:g}: expected a number in {}{:g}, {:g}]{}", option, value, open_lo ? "(" : "[", lo, hi,
                               unit));
}

} // namespace

void check_relax_settings(const RelaxSettings& s)
{
    if (s.steps < 1 || s.steps > 10000000) fail_usage(fmt::format("--steps {}: expected 1 to 10000000 steps", s.steps));
    require_range(s.tolerance, 0, 1, false, "--tolerance", " (units of h per step)");
    require_range(s.gamma, 0, 1e3, true, "--gamma", "");
    // Kick-drift-kick is stable for omega dt < 2; the fastest SPH sound waves have omega ~ 2 c / h.
    require_range(s.time_step, 0, 0.5, true, "--dt", " (units of h / c)");
    require_range(s.damping, 0, 100, false, "--damping", " (units of c / h)");
    require_range(s.alpha, 0, 10, true, "--alpha", "");
    require_range(s.max_move, 0, 0.5, true, "--max-move", " (units of h)");
    if (s.threads < 0 || s.threads > 1024) fail_usage(fmt::format("--threads {}: expected 0 to 1024", s.threads));
}

} // namespace sphkern
