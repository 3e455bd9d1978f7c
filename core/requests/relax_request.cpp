#include "requests/relax_request.hpp"

#include "particles/particle_volumes.hpp"
#include "relax/glass_quality.hpp"
#include "requests/particles_request.hpp"
#include "support/error.hpp"

#include <fmt/format.h>

namespace sphkern {

RelaxSources relax_sources(FrontEnd f)
{
    auto n = [f](const char* key) { return value_named(f, key); };
    return {smoothing_sources(f), n("method"), n("steps"), n("tolerance"), n("gamma"),   n("dt"),
            n("damping"),         n("alpha"),  n("max_move"), n("threads"), n("rdf_max"), n("rdf_bins")};
}

RelaxMethod relax_method_of(const std::string& name, const ValueSource& source)
{
    if (name == "pressure") return RelaxMethod::pressure;
    if (name == "shift") return RelaxMethod::shift;
    source.fail(fmt::format("\"{}\" is unknown, expected pressure or shift", name));
}

void check_relax_settings(const RelaxSettings& s, const RelaxSources& sources)
{
    check_range(s.steps, 1, 10000000, sources.steps);
    check_number(s.tolerance, 0, 1, LowEnd::closed, sources.tolerance, " (units of h per step)");
    check_number(s.gamma, 0, 1e3, LowEnd::open, sources.gamma);
    // Kick-drift-kick is stable for omega dt < 2; the fastest SPH sound waves have omega ~ 2 c / h.
    check_number(s.time_step, 0, 0.5, LowEnd::open, sources.dt, " (units of h / c)");
    check_number(s.damping, 0, 100, LowEnd::closed, sources.damping, " (units of c / h)");
    check_number(s.alpha, 0, 10, LowEnd::open, sources.alpha);
    check_number(s.max_move, 0, 0.5, LowEnd::open, sources.max_move, " (units of h)");
    check_threads(s.threads, sources.threads);
}

void check_rdf(double r_max, std::size_t bins, const RelaxSources& sources)
{
    check_rdf_settings(r_max, bins, sources.rdf_max, sources.rdf_bins);
}

double relax_h(const SmoothingSpec& spec, const ParticleSet& set, const Kernel& kernel, const SmoothingSources& sources)
{
    if (!set.box)
        fail_input(fmt::format("{}: relaxation needs a periodic box; expected a lattice block, poisson or a file with a box",
                               set.name));
    check_smoothing_fits(spec, set, sources);
    return smoothing_lengths(set, kernel, spec, mean_volume(set)).front();
}

} // namespace sphkern
