#include "requests/pairing_request.hpp"

#include "requests/settings/command_settings.hpp"

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
    const SettingTable& declared = settings_of("pairing");
    check_setting(declared["samples"], r.samples, sources.samples);
    if (r.samples > 1 && r.k_max == r.k_min) sources.samples.fail("several samples need kmin < kmax");
    check_setting(declared["noise"], r.noise, sources.noise);
    check_setting(declared["duration"], r.duration, sources.duration);
    check_setting(declared["damping"], r.damping, sources.damping);
    check_setting(declared["dt"], r.time_step, sources.dt);
    check_setting(declared["gamma"], r.gamma, sources.gamma);
    check_horizon(r.horizon, sources.horizon.name);
    check_setting(declared["threads"], r.threads, sources.threads);
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
