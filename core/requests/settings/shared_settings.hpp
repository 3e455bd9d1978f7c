// The settings several commands share, declared once for all of them.
#pragma once

#include "requests/settings/setting.hpp"

#include <string>
#include <vector>

namespace sphkern {

// The positionals most commands start with: "Kernel name or plugin file", "Lattice name or file".
Setting kernel_name();
Setting lattice_name();
// --ap/a_p, --gravity, --site, --shells and --continue-past-support, as eps and roots take them.
std::vector<Setting> evaluation_settings();
// --code: "Give the resolution as an SPH code sets it: swift, ..., with its parameter below".
Setting code_choice();
// Each code's parameter as its option (--eta, --hfact, ...: "With --code gadget2 or gadget4: ..."),
// on the command line only (Python gives `value` beside `code`), but those in `skip`.
std::vector<Setting> code_parameters(const std::vector<std::string>& skip = {});
// Each code's parameter as a sweep: --eta-range A B, ... (assess on a particle file).
std::vector<Setting> parameter_ranges();
// Python's `value` beside `code`: the code's parameter, whichever code.
Setting code_value();
// The source of a particle set's options: a lattice block (--size, --cell, --sigma, --seed),
// a Poisson set (--count, --dim, --box) or a file's (--box, --particle-radius, --array).
std::vector<Setting> source_settings();
// The settings on the command line only, but those named.
std::vector<Setting> except_in_python(std::vector<Setting> settings, const std::vector<std::string>& kept);
// sphkern's own h over the mean spacing (with the command's help) and the neighbour number
// N_H, in (0, 100] and [1, 1e5]: particles and relax alike, and their sweeps.
Setting h_over_l_setting(std::string help);
Setting nh_setting();
// --set NAME=VALUE, Python's params.
Setting kernel_parameters();
// --plugin and --json, on the command line only.
Setting plugin_files();
Setting json_output();

} // namespace sphkern
