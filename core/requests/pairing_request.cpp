#include "requests/pairing_request.hpp"

#include "codes/code_table.hpp"

#include "requests/particles_request.hpp"
#include "stability/dispersion.hpp"

namespace sphkern {

PairingSources pairing_sources(FrontEnd f)
{
    auto n = [f](const char* key) { return value_named(f, key); };
    return {n("kmin"),    n("kmax"), n("samples"), n("noise"),   n("duration"),
            n("damping"), n("dt"),   n("gamma"),   n("horizon"), n("threads")};
}

void check_pairing_request(const PairingRequest& r, const PairingSources& sources)
{
    check_k_interval(r.k_min, r.k_max, sources.k_min, sources.k_max, IntervalEnds::may_meet);
    check_range(r.samples, 1, 1000, sources.samples);
    if (r.samples > 1 && r.k_max == r.k_min) sources.samples.fail("several samples need kmin < kmax");
    check_number(r.noise, 0, 0.01, LowEnd::open, sources.noise, " (units of d; the motion starts linear)");
    check_number(r.duration, 0, 1e4, LowEnd::open, sources.duration, " (units of d / c)");
    // The motion is relax's pressure method: its ranges.
    check_number(r.damping, 0, 100, LowEnd::closed, sources.damping, " (units of c / h)");
    check_number(r.time_step, 0, 0.5, LowEnd::open, sources.dt, " (units of h / c)");
    check_number(r.gamma, min_gamma, 1e3, LowEnd::closed, sources.gamma);
    check_horizon(r.horizon, sources.horizon.name);
    check_threads(r.threads, sources.threads);
}

std::optional<CodeK> pairing_code_k(PairingRequest& request, const std::optional<CodeSetting>& setting,
                                    const CodeSettingSources& sources, const Kernel& kernel, const Lattice& lattice)
{
    if (!setting) return std::nullopt;
    require_lattice_volume(code_profile(setting->code, sources.code), "the motion of a lattice block");
    const EvaluationSources unnamed{}; // the default a_p, site and gravity, which every lattice has
    const auto code = k_of_code_setting(*setting, sources, kernel, lattice, resolve_evaluation({}, unnamed, lattice));
    request.k_min = request.k_max = code.k;
    request.samples = 1;
    check_k(code.k, sources.value);
    return code;
}

} // namespace sphkern
