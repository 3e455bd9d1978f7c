// A code's own setting on the command line (`eps`, `assess`, `surface`, `pairing`): --code NAME and that code's
// parameter by its own name (--eta, --hfact, --nngb, --hdx, --coefh, --particle-radius), or --k.
#pragma once

#include "cli/options.hpp"
#include "requests/eps_request.hpp"

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sphkern::cli {

struct SettingOptions {
    std::optional<double> k;
    std::string code;
    // Each code's parameter by its name ("eta", "hfact", ...), as its option fills it.
    std::map<std::string, std::optional<double>> parameters;
};

// --k, --code and every code's parameter (code_table), SPlisHSPlasH's --particle-radius too.
void add_setting_options(Command command, SettingOptions& options);

// The codes' parameters but SWIFT's --eta and SPlisHSPlasH's --particle-radius, for a command
// that declares those (and --code) itself (`particles`, `relax`: sphkern's own --eta beside
// --code swift, a file's particle radius).
void add_code_parameters(Command command, SettingOptions& options);

// Whether any of --k, --code and the codes' parameters is given.
bool setting_given(const SettingOptions& options);

// The code's setting: its parameter given only with --code and alone, or none for --k.
std::optional<CodeSetting> code_setting(const SettingOptions& options);

// --code NAME with --eta among the codes' parameters (`particles`, `relax`, whose own ratio is
// --h-over-l): with --code swift, `eta` is SWIFT's. The code with its parameter's value, or
// none (alone); nullopt without --code. A parameter without --code, or another code's, is refused.
struct CodeChoice {
    std::string code;
    std::optional<double> value;
};
std::optional<CodeChoice> code_beside_own_eta(const SettingOptions& codes, const std::optional<double>& eta);

// --eta without --code: refused, naming sphkern's own --h-over-l (SWIFT's eta is a code's setting).
void refuse_eta_without_code(const SettingOptions& codes, const std::optional<double>& eta);

// --neighbours-by number|mass and --bias-correction beside --code with its parameter (what the
// code's density solve counts, and the bias it subtracts); Error(usage) for another word, or
// without a code's parameter (`setting` null).
void set_density_solve(CodeSetting* setting, const std::string& neighbours_by, bool bias_correction);

// Each code's parameter as a sweep, --eta-range A B, --hfact-range A B, ... (`assess` on a file).
void add_parameter_ranges(Command command, std::map<std::string, std::vector<double>>& ranges);
// The range given, as its code's parameter (an Error(usage) for another code's): its option and
// values, or nullopt.
std::optional<std::pair<std::string, std::vector<double>>> parameter_range(
    const std::map<std::string, std::vector<double>>& ranges, const std::string& code);

// "--code" and the code's parameter ("--eta"), for the request's errors.
std::pair<ValueSource, ValueSource> code_sources(const SettingOptions& options);

} // namespace sphkern::cli
