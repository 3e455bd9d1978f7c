#include "requests/settings/command_settings.hpp"

#include "requests/settings/shared_settings.hpp"

namespace sphkern {

SettingTable eps_settings()
{
    return {"eps",
            {{kernel_name(), lattice_name(),
              number("k", "", "Smoothing coefficient, h = k d (or --code and the code's own setting)"),
              code_choice().command_line_only()},
             code_parameters(),
             {word("axis", "k", "The scale of --k: k (h/d) or h_over_l (h/V^(1/D))")},
             evaluation_settings(),
             {kernel_parameters(), plugin_files(), json_output()}}};
}

} // namespace sphkern
