#include "requests/smoothing_request.hpp"

#include "requests/settings/command_settings.hpp"

#include "support/error.hpp"

#include <fmt/format.h>

#include <cmath>

namespace sphkern {

SmoothingSources smoothing_sources(FrontEnd f)
{
    return {value_named(f, "h_over_l"), value_named(f, "nh"), value_named(f, "k"), value_named(f, "support_per_h"),
            value_named(f, "code")};
}

SmoothingSpec smoothing_spec(const SmoothingArguments& given, const SmoothingSources& sources, SmoothingSpec fallback)
{
    require_at_most_one({{given.eta.has_value(), &sources.eta},
                         {given.nh.has_value(), &sources.nh},
                         {given.k.has_value(), &sources.k}});
    // The bounds are particles' and relax's alike (shared_settings).
    const SettingTable& declared = settings_of("particles");
    if (given.eta) check_setting(declared["h_over_l"], *given.eta, sources.eta);
    if (given.nh) check_setting(declared["nh"], *given.nh, sources.nh);
    if (given.k) check_k(*given.k, sources.k);
    if (given.eta) return {SmoothingRule::eta, *given.eta, 0};
    if (given.nh) return {SmoothingRule::nh, *given.nh, 0};
    if (given.k) return {SmoothingRule::k, *given.k, 0};
    return fallback;
}

void check_smoothing_fits(const SmoothingSpec& spec, const ParticleSet& set, const SmoothingSources& sources)
{
    const std::string others = fmt::format("give {} E or {} N", sources.eta.name, sources.nh.name);
    if (spec.rule == SmoothingRule::k && set.spacing <= 0)
        fail_input(
            fmt::format("{}: {} needs a lattice (h = k d); for other sets {}", set.name, sources.k.name, others));
    if (spec.rule != SmoothingRule::file) return;
    if (set.h.empty()) fail_input(fmt::format("{}: the file has no smoothing lengths; {}", set.name, others));
    const double x = spec.support_per_h > 0 ? spec.support_per_h : set.support_per_h;
    // A SWIFT file without /HydroScheme holds no kernel gamma: the code's name gives it.
    const std::string code = sources.code.name.empty()
                                 ? ""
                                 : fmt::format(", {} NAME, the code that wrote it ({} swift: SWIFT's kernel gamma of "
                                               "the kernel)",
                                               sources.code.name, sources.code.name);
    if (!(x > 0) || !std::isfinite(x))
        fail_input(fmt::format("{}: the file's smoothing lengths need a convention: {} X, the support radius over the "
                               "stored h (GADGET 1, SWIFT its kernel gamma, PySPH and Phantom the kernel's R, "
                               "DualSPHysics 2){}, or {}",
                               set.name, sources.support_per_h.name, code, others));
}

void check_file_kernel(const SmoothingSpec& spec, const ParticleSet& set, const std::string& kernel,
                       const SmoothingSources& sources)
{
    if (spec.rule != SmoothingRule::file || spec.support_per_h > 0 || set.file_kernel.empty() ||
        set.file_kernel_name == kernel)
        return;
    fail_input(fmt::format("{}: the file's h and its kernel gamma {} are for its kernel {}, not {}; expected that "
                           "kernel, or {} X to map its h to {}'s support",
                           set.name, set.support_per_h, file_kernel_text(set), kernel, sources.support_per_h.name,
                           kernel));
}

std::string file_kernel_text(const ParticleSet& set)
{
    return fmt::format("\"{}\"{}", set.file_kernel,
                       set.file_kernel_name.empty() ? "" : " (sphkern's " + set.file_kernel_name + ")");
}

SmoothingSpec smoothing_of(const SmoothingArguments& given, const ParticleSet& set, const SmoothingSources& sources,
                           bool file_h_allowed)
{
    const bool rule_given = given.eta || given.nh || given.k;
    SmoothingSpec spec = smoothing_spec(given, sources);
    if (!rule_given && !set.h.empty() && file_h_allowed)
        spec = {SmoothingRule::file, 0, given.support_per_h.value_or(0)};
    // A code whose support is a number of particle radii the file does not hold (SPlisHSPlasH).
    if (!rule_given && set.h.empty() && set.support_per_radius > 0)
        fail_input(fmt::format("{}: the file holds no h and no particle radius (its support is {} radii); give "
                               "--particle-radius R, the scene's particle radius, or {} E or {} N",
                               set.name, set.support_per_radius, sources.eta.name, sources.nh.name));
    const auto x = given.support_per_h;
    if (x && (spec.rule != SmoothingRule::file || !(*x > 0) || !std::isfinite(*x)))
        sources.support_per_h.fail(fmt::format("maps a file's h (a positive finite number); it does not go with {}, "
                                               "{} or {}",
                                               sources.eta.name, sources.nh.name, sources.k.name));
    check_smoothing_fits(spec, set, sources);
    return spec;
}

} // namespace sphkern
