#include "requests/code_setting.hpp"

#include "analysis/hydrostatic_errors.hpp"
#include "codes/code_table.hpp"
#include "requests/smoothing_request.hpp"
#include "support/error.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace sphkern {

namespace {

PairSmoothing pair_smoothing(const CodeProfile& profile)
{
    return profile.pair_mean ? PairSmoothing::mean : PairSmoothing::own;
}

const char* count_name(NeighbourCount counts) { return counts == NeighbourCount::number ? "number" : "mass"; }

// The count asked for, where the code can count that way; else an Error naming the code.
NeighbourCount counts_of(const CodeProfile& profile, const CodeSetting& setting, const CodeSettingSources& sources)
{
    if (!setting.counts) return profile.counts;
    if (!profile.from_sph_density)
        sources.code.fail(fmt::format("{}: {} sets h from the mean spacing, with no neighbour count; expected no count",
                                      setting.code, profile.title));
    if (*setting.counts != profile.counts && profile.count_switch.empty())
        sources.code.fail(fmt::format("{}: {} counts neighbours by {} only ({}); expected that count", setting.code,
                                      profile.title, count_name(profile.counts), profile.count_source));
    return *setting.counts;
}

// The h (in d) that gives the code's parameter `value` at rest where m / rho = a_p d^D: the
// parameter is linear in h, or in h^D for a neighbour number.
double rest_h(const CodeProfile& profile, const Kernel& kernel, int dimension, double a_p, double value)
{
    const double at_one = code_parameter(profile, kernel, dimension, a_p, 1, 0);
    return std::pow(value / at_one, profile.counts_neighbours ? 1.0 / dimension : 1.0);
}

// Where the code solves h from each particle's SPH density, a parameter at or below that of a
// particle with no neighbour inside its support (self density m W(0) / h^D, so that
// (m / rho)^(1/D) = h / W(0)^(1/D)) has no h to settle at: h shrinks towards zero. Refused
// before any sum, naming the source.
void require_neighbour_reach(const CodeProfile& profile, const Kernel& kernel, int dimension, double value,
                             const ValueSource& source)
{
    if (!profile.from_sph_density) return;
    const double lone =
        profile.parameter_of(kernel, dimension, std::pow(kernel.w(0, dimension, 1), 1.0 / dimension), 1);
    if (!(value > lone))
        source.fail(
            fmt::format("{:g}: expected more than {:.6g}, the {} of a particle with no neighbour inside its support, "
                        "below which {}'s density solve has no h",
                        value, lone, profile.parameter, profile.title));
}

// The fraction of a particle's own density term the code subtracts; an Error naming the code
// where it has no such correction.
double self_bias(const CodeProfile& profile, const Kernel& kernel, int dimension, double value,
                 const CodeSettingSources& sources)
{
    if (!profile.self_bias) {
        std::vector<std::string> codes;
        for (const auto& p : code_profiles())
            if (p.self_bias) codes.push_back(fmt::format("{} ({})", p.name, p.bias_switch));
        sources.code.fail(fmt::format("{}: {} subtracts no bias from the density; expected a code that does: {}",
                                      profile.name, profile.title, fmt::join(codes, ", ")));
    }
    return profile.self_bias(kernel, dimension, value, sources.value);
}

} // namespace

std::optional<CodeSetting> code_setting_of(const std::optional<std::string>& code, std::optional<double> value,
                                           const CodeSettingSources& sources)
{
    if (code && !value)
        throw Error(sources.code.code, fmt::format("{} = {}: expected {}, the code's parameter, too", sources.code.name,
                                                   *code, sources.value.name));
    if (value && !code)
        throw Error(sources.value.code,
                    fmt::format("{}: is a code's parameter; expected {} too", sources.value.name, sources.code.name));
    if (!code) return std::nullopt;
    return CodeSetting{*code, *value};
}

void check_code_setting(const CodeSetting& setting, const CodeSettingSources& sources)
{
    const auto& profile = code_profile(setting.code, sources.code);
    if (profile.counts_neighbours) check_positive(setting.value, sources.value);
    else check_number(setting.value, 0, k_limit, LowEnd::open, sources.value);
}

CodeK k_of_code_setting(const CodeSetting& setting, const CodeSettingSources& sources, const Kernel& kernel,
                        const Lattice& lattice, const Evaluation& evaluation)
{
    const auto& profile = code_profile(setting.code, sources.code);
    const int dim = lattice.dimension;
    require_code_kernel(profile, kernel, dim);
    const double rest_k = rest_h(profile, kernel, dim, evaluation.a_p, setting.value);
    const double k_max = std::min(k_limit, 1.5 * rest_k + 0.5); // the density moves k by far less
    // A setting so large that the lattice's sums reach past their limit is the setting's fault: named as given.
    const HydrostaticErrors errors = [&] {
        try {
            return HydrostaticErrors(kernel, lattice, evaluation.site, evaluation.a_p, evaluation.gravity, k_max,
                                     evaluation.mode);
        } catch (const Error& e) {
            if (e.code() != ExitCode::input) throw;
            sources.value.fail(fmt::format("{:g}: its k, about {:.4g}, is more than the lattice's sums can reach ({})",
                                           setting.value, rest_k, e.what()));
        }
    }();
    auto eps_rho = [&](double k) { return errors.at(k).eps_rho; };
    CodeK code{setting, profile.parameter, 0, 0, std::nullopt};
    code.k = k_of_code_parameter(profile, kernel, dim, evaluation.a_p, setting.value, k_max, eps_rho, sources.value);
    code.value_at_k = code_parameter(profile, kernel, dim, evaluation.a_p, code.k, eps_rho(code.k));
    if (profile.sets_volume) code.a_p = code_volume(profile, dim, setting.value);
    return code;
}

SmoothingSpec code_smoothing(const CodeSetting& setting, const CodeSettingSources& sources, const Kernel& kernel,
                             int dimension)
{
    const auto& profile = code_profile(setting.code, sources.code);
    require_code_kernel(profile, kernel, dimension);
    require_lattice_volume(profile, "a particle set");
    require_neighbour_reach(profile, kernel, dimension, setting.value, sources.value);
    // h = c (m / rho)^(1/D): c is the h at rest for m / rho = 1.
    const double c = rest_h(profile, kernel, dimension, 1, setting.value);
    SmoothingSpec spec{profile.from_sph_density ? SmoothingRule::density : SmoothingRule::eta, c, 0,
                       pair_smoothing(profile), counts_of(profile, setting, sources) == NeighbourCount::number};
    if (setting.bias_correction) spec.self_weight = 1 - self_bias(profile, kernel, dimension, setting.value, sources);
    return spec;
}

SmoothingSpec stored_code_smoothing(const std::string& code, const CodeSettingSources& sources, const Kernel& kernel,
                                    const ParticleSet& set)
{
    const auto& profile = code_profile(code, sources.code);
    require_code_kernel(profile, kernel, set.dimension);
    require_lattice_volume(profile, "a particle set");
    if (set.h.empty())
        fail_input(fmt::format("{}: the set stores no h; with {} {}, expected {} too (the code's parameter)", set.name,
                               sources.code.name, code, sources.value.name));
    if (!set.file_kernel.empty() && set.file_kernel_name != kernel.name())
        fail_input(fmt::format("{}: the file's h is for its kernel {}, not {}; expected that kernel", set.name,
                               file_kernel_text(set), kernel.name()));
    return {SmoothingRule::file, 0, code_support_per_h(profile, kernel, set.dimension), pair_smoothing(profile)};
}

nlohmann::json code_k_json(const CodeK& code)
{
    nlohmann::json out = {{"name", code.setting.code},
                          {"parameter", code.parameter},
                          {"value", code.setting.value},
                          {"value_at_k", code.value_at_k}};
    if (code.a_p) out["a_p"] = *code.a_p;
    return out;
}

nlohmann::json code_answer_json(const CodeSetting& setting)
{
    const auto& profile = code_profile(setting.code, ValueSource::argument("code"));
    nlohmann::json out = {{"name", setting.code},
                          {"parameter", profile.parameter},
                          {"value", setting.value},
                          {"h_from", profile.from_sph_density ? "sph_density" : "mean_spacing"}};
    if (profile.from_sph_density) out["counts"] = count_name(setting.counts.value_or(profile.counts));
    if (setting.bias_correction) out["bias_correction"] = profile.bias_switch;
    return out;
}

std::string code_answer_text(const CodeSetting& setting)
{
    const auto& profile = code_profile(setting.code, ValueSource::argument("code"));
    return fmt::format(
        "{} {} = {:.10g}: h from {}{}", setting.code, profile.parameter, setting.value,
        !profile.from_sph_density ? "the mean spacing"
        : setting.counts.value_or(profile.counts) == NeighbourCount::number
            ? "each particle's neighbour count sum_j W, by number as the code counts (solved for every particle)"
            : "each particle's SPH density (solved for every particle)",
        setting.bias_correction ? ", less the code's bias (" + profile.bias_switch + ")" : "");
}

nlohmann::json stored_code_json(const std::string& code, const Kernel& kernel, int dimension)
{
    const auto& profile = code_profile(code, ValueSource::argument("code"));
    return {{"name", code},
            {"parameter", profile.parameter},
            {"h_from", "file"},
            {"support_per_h", code_support_per_h(profile, kernel, dimension)},
            {"pair_h", profile.pair_mean ? "mean" : "own"}};
}

std::string stored_code_text(const std::string& code, const Kernel& kernel, int dimension)
{
    const auto& profile = code_profile(code, ValueSource::argument("code"));
    return fmt::format("{}: the file's h as {} stores it, support {:.10g} h, a pair's h {}", code, code,
                       code_support_per_h(profile, kernel, dimension),
                       profile.pair_mean ? "the mean of its two" : "the particle's own");
}

} // namespace sphkern
