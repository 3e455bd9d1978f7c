#include "cli/code_options.hpp"

#include "codes/code_table.hpp"
#include "support/error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

namespace sphkern::cli {

namespace {

// A code's parameter as an option: "particle_radius" is --particle-radius.
std::string option_of(std::string parameter)
{
    std::replace(parameter.begin(), parameter.end(), '_', '-');
    return "--" + parameter;
}

// Each code's parameter as an option (a parameter two codes share, once), but those in `skip`.
void add_parameters(Command c, SettingOptions& o, const std::vector<std::string>& skip)
{
    for (const auto& p : code_profiles())
        if (std::find(skip.begin(), skip.end(), p.parameter) == skip.end() && !o.parameters.contains(p.parameter))
            c.add_setting(p.parameter, o.parameters[p.parameter]);
}

} // namespace

void add_setting_options(Command c, SettingOptions& o)
{
    c.add_setting("k", o.k);
    c.add_setting("code", o.code);
    add_parameters(c, o, {});
}

void add_code_parameters(Command c, SettingOptions& o) { add_parameters(c, o, {"eta", "particle_radius"}); }

bool setting_given(const SettingOptions& o)
{
    return o.k || !o.code.empty() ||
           std::any_of(o.parameters.begin(), o.parameters.end(), [](const auto& p) { return p.second.has_value(); });
}

namespace {

// The code and its parameter's value as given (none: named alone); nullopt without --code. A
// parameter without --code, or another code's, is refused. `eta` is the option --eta fills.
std::optional<CodeChoice> code_choice(const SettingOptions& o, const std::optional<double>& eta)
{
    std::vector<std::pair<std::string, const std::optional<double>*>> given;
    for (const auto& [name, value] : o.parameters) given.emplace_back(name, &value);
    if (!o.parameters.contains("eta")) given.emplace_back("eta", &eta);
    if (o.code.empty()) {
        for (const auto& [name, value] : given)
            if (value->has_value())
                throw Error(ExitCode::usage,
                            fmt::format("{} is a code's setting; expected --code too", option_of(name)));
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
    const auto choice = code_choice(o, std::nullopt);
    if (!choice) {
        if (!o.k) throw Error(ExitCode::usage, "--k is required (or --code and the code's setting)");
        return std::nullopt;
    }
    const std::string parameter = option_of(code_profile(o.code, ValueSource::option("--code")).parameter);
    if (!choice->value)
        throw Error(ExitCode::usage, fmt::format("--code {}: expected its setting, {}", o.code, parameter));
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
        throw Error(ExitCode::usage,
                    "--eta is SWIFT's eta, a code's setting (--code swift --eta); sphkern's own h over the "
                    "mean spacing is --h-over-l");
}

std::pair<ValueSource, ValueSource> code_sources(const SettingOptions& o)
{
    const std::string parameter = o.code.empty() ? "" : code_profile(o.code, ValueSource::option("--code")).parameter;
    return {ValueSource::option("--code"), ValueSource::option(option_of(parameter))};
}

void set_density_solve(CodeSetting* setting, const std::string& neighbours_by, bool bias_correction)
{
    if (!setting && !neighbours_by.empty())
        throw Error(ExitCode::usage,
                    "--neighbours-by chooses what a code's density solve counts; expected --code with its "
                    "parameter (h solved on the set)");
    if (!setting && bias_correction)
        throw Error(ExitCode::usage,
                    "--bias-correction is the code's correction of its density solve; expected --code with "
                    "its parameter (h solved on the set)");
    if (!setting) return;
    setting->bias_correction = bias_correction;
    if (neighbours_by.empty()) return;
    if (neighbours_by != "number" && neighbours_by != "mass")
        throw Error(ExitCode::usage, fmt::format("--neighbours-by {}: expected number or mass", neighbours_by));
    setting->counts = neighbours_by == "number" ? NeighbourCount::number : NeighbourCount::mass;
}

void add_parameter_ranges(Command c, std::map<std::string, std::vector<double>>& ranges)
{
    for (const auto& p : code_profiles()) {
        if (ranges.contains(p.parameter)) continue;
        c.add_setting(p.parameter + "_range", ranges[p.parameter]).expected(2);
    }
}

std::optional<std::pair<std::string, std::vector<double>>> parameter_range(
    const std::map<std::string, std::vector<double>>& ranges, const std::string& code)
{
    const std::string parameter = code.empty() ? "" : code_profile(code, ValueSource::option("--code")).parameter;
    std::optional<std::pair<std::string, std::vector<double>>> found;
    for (const auto& [name, values] : ranges) {
        if (values.empty()) continue;
        if (name != parameter)
            throw Error(ExitCode::usage,
                        fmt::format("{}-range sweeps {}; expected --code with that parameter{}", option_of(name), name,
                                    code.empty() ? "" : fmt::format(" ({} sets {})", code, parameter)));
        found = std::pair{option_of(name) + "-range", values};
    }
    return found;
}

} // namespace sphkern::cli
