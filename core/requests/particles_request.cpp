#include "requests/particles_request.hpp"

#include "requests/settings/command_settings.hpp"

#include "lattices/numeric_inputs.hpp"
#include "support/error.hpp"

#include <fmt/format.h>

namespace sphkern {

ParticleSources particle_sources(FrontEnd f)
{
    auto n = [f](const char* key) { return value_named(f, key); };
    return {smoothing_sources(f),
            n("h_over_l_range"),
            n("nh_range"),
            n("steps"),
            n("volume"),
            n("gravity"),
            n("depth"),
            n("rho0"),
            n("threads"),
            n("histogram"),
            f == FrontEnd::command_line ? ValueSource::option("--csv and --vtk") : n("arrays"),
            {n("code"), n("value")}}; // the command line names the code's parameter itself
}

void name_code(ParticleArguments& given, const std::string& code, std::optional<double> value)
{
    if (value) given.code = CodeSetting{code, *value};
    else given.stored_h_code = code;
}

namespace {

std::optional<SmoothingSweep> sweep_of(const ParticleArguments& given, const ParticleSources& sources)
{
    if (!given.eta_range && !given.nh_range) return std::nullopt;
    const bool eta = given.eta_range.has_value();
    const auto& [from, to] = eta ? *given.eta_range : *given.nh_range;
    if (given.per_particle_files)
        sources.per_particle_files.fail("write one h per particle; they do not go with a sweep");
    return checked_sweep(eta ? SmoothingRule::eta : SmoothingRule::nh, from, to, given.steps,
                         eta ? sources.eta_range : sources.nh_range, sources.steps);
}

} // namespace

SmoothingSweep checked_sweep(SmoothingRule rule, double from, double to, int steps, const ValueSource& range,
                             const ValueSource& steps_source)
{
    // A sweep's values are h_over_l's or nh's: their bounds.
    const Setting& swept = settings_of("particles")[rule == SmoothingRule::eta ? "h_over_l" : "nh"];
    for (const double value : {from, to}) check_setting(swept, value, range);
    if (!(to > from)) range.fail(fmt::format("[{}, {}]: expected min < max", from, to));
    check_setting(settings_of("particles")["steps"], steps, steps_source);
    return {rule, from, to, steps};
}

ParticleRequest particle_request(const ParticleArguments& given, const Kernel& kernel, const ParticleSet& set,
                                 const ParticleSources& sources)
{
    const auto& s = sources.smoothing;
    require_at_most_one({{given.smoothing.eta.has_value(), &s.eta},
                         {given.smoothing.nh.has_value(), &s.nh},
                         {given.smoothing.k.has_value(), &s.k},
                         {given.eta_range.has_value(), &sources.eta_range},
                         {given.nh_range.has_value(), &sources.nh_range}});
    ParticleRequest request;
    request.sweep = sweep_of(given, sources);
    if (given.code || given.stored_h_code) {
        if (given.smoothing.eta || given.smoothing.nh || given.smoothing.k || request.sweep)
            sources.code.code.fail("gives h for one setting; expected no " + s.eta.name + ", " + s.nh.name + ", " +
                                   s.k.name + " or sweep beside it");
        if (given.smoothing.support_per_h)
            sources.code.code.fail(
                fmt::format("gives the support over h; expected no {} beside it", s.support_per_h.name));
        if (given.stored_h_code) {
            request.smoothing = stored_code_smoothing(*given.stored_h_code, sources.code, kernel, set);
        } else {
            check_code_setting(*given.code, sources.code);
            request.smoothing = code_smoothing(*given.code, sources.code, kernel, set.dimension);
        }
    } else {
        request.smoothing = smoothing_of(given.smoothing, set, s, !request.sweep);
    }
    check_file_kernel(request.smoothing, set, kernel.name(), s);
    if (given.volume) request.volume = at_source(sources.volume, [&] { return parse_volume_model(*given.volume); });
    request.given_volumes = given.volumes;
    if (given.gravity) request.gravity = direction_of(*given.gravity, set.dimension, sources.gravity);
    const SettingTable& declared = settings_of("particles");
    check_setting(declared["depth"], given.depth, sources.depth);
    request.depth = given.depth;
    if (given.rho0) check_positive(*given.rho0, sources.rho0);
    request.rho0 = given.rho0;
    check_setting(declared["threads"], given.threads, sources.threads);
    request.threads = given.threads;
    check_setting(declared["histogram"], static_cast<double>(given.histogram), sources.histogram);
    request.histogram_bins = static_cast<std::size_t>(given.histogram);
    request.vectors = given.per_particle_files;
    return request;
}

} // namespace sphkern
