#include "cli/code_options.hpp"

#include "analysis/code_profiles.hpp"
#include "support/error.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace sphkern::cli {

void add_setting_options(Command c, SettingOptions& o, const std::string& k_help)
{
    c.add_option("--k", o.k, k_help);
    c.add_option("--code", o.code, "Give the resolution as an SPH code sets it: swift, phantom, gadget2, gadget4, "
                                   "pysph, dualsphysics or splishsplash, with its parameter below");
    c.add_option("--eta", o.eta, "With --code swift: SWIFT's eta, h = eta (m / rho)^(1/D)");
    add_code_parameters(c, o);
    c.add_option("--particle-radius", o.particle_radius,
                 "With --code splishsplash: its particle radius r in d, support 4 r and volume 0.8 (2 r)^D");
}

void add_code_parameters(Command c, SettingOptions& o)
{
    c.add_option("--hfact", o.hfact, "With --code phantom: Phantom's hfact, h = hfact (m / rho)^(1/D)");
    c.add_option("--nngb", o.nngb, "With --code gadget2 or gadget4: the weighted neighbour number");
    c.add_option("--hdx", o.hdx, "With --code pysph: PySPH's hdx, h = hdx dx");
    c.add_option("--coefh", o.coefh, "With --code dualsphysics: DualSPHysics' coefh, h = coefh sqrt(D) dp");
}

bool setting_given(const SettingOptions& o)
{
    return o.k || !o.code.empty() || o.eta || o.hfact || o.nngb || o.hdx || o.coefh;
}

namespace {

// A code's parameter as an option: "particle_radius" is --particle-radius.
std::string option_of(std::string parameter)
{
    std::replace(parameter.begin(), parameter.end(), '_', '-');
    return "--" + parameter;
}

} // namespace

namespace {

// The code and its parameter's value as given (none: named alone); nullopt without --code. A
// parameter without --code, or another code's, is refused. `eta` is the option --eta fills.
std::optional<CodeChoice> code_choice(const SettingOptions& o, const std::optional<double>& eta)
{
    const std::pair<const char*, const std::optional<double>*> given[] = {
        {"eta", &eta},     {"hfact", &o.hfact}, {"nngb", &o.nngb}, {"hdx", &o.hdx}, {"coefh", &o.coefh},
        {"particle_radius", &o.particle_radius}};
    if (o.code.empty()) {
        for (const auto& [name, value] : given)
            if (value->has_value())
                throw Error(ExitCode::usage, fmt::format("{} is a code's setting; expected --code too", option_of(name)));
        return std::nullopt;
    }
    const std::string parameter = code_profile(o.code, ValueSource::option("--code")).parameter;
    CodeChoice choice{o.code, std::nullopt};
    for (const auto& [name, value] : given) {
        if (!value->has_value()) continue;
        if (name != parameter)
            throw Error(ExitCode::usage, fmt::format("{}: {} sets its resolution with {}", option_of(name), o.code,
                                                     option_of(parameter)));
        choice.value = **value;
    }
    return choice;
}

} // namespace

std::optional<CodeSetting> code_setting(const SettingOptions& o)
{
    const auto choice = code_choice(o, o.eta);
    if (!choice) {
        if (!o.k) throw Error(ExitCode::usage, "--k is required (or --code and the code's setting)");
        return std::nullopt;
    }
    const std::string parameter = option_of(code_profile(o.code, ValueSource::option("--code")).parameter);
    if (!choice->value) throw Error(ExitCode::usage, fmt::format("--code {}: expected its setting, {}", o.code, parameter));
    if (o.k) throw Error(ExitCode::usage, fmt::format("give one of --k and {}", parameter));
    return CodeSetting{o.code, *choice->value};
}

std::optional<CodeChoice> code_beside_own_eta(const SettingOptions& o, const std::optional<double>& eta)
{
    refuse_eta_without_code(o, eta);
    return code_choice(o, eta);
}

void refuse_eta_without_code(const SettingOptions& o, const std::optional<double>& eta)
{
    if (eta && o.code.empty())
        throw Error(ExitCode::usage, "--eta is SWIFT's eta, a code's setting (--code swift --eta); sphkern's own h over the "
                                     "mean spacing is --h-over-l");
}

std::pair<ValueSource, ValueSource> code_sources(const SettingOptions& o)
{
    const std::string parameter = o.code.empty() ? "" : code_profile(o.code, ValueSource::option("--code")).parameter;
    return {ValueSource::option("--code"), ValueSource::option(option_of(parameter))};
}

} // namespace sphkern::cli
