#include "requests/settings/command_settings.hpp"

#include "requests/settings/shared_settings.hpp"

namespace sphkern {

SettingTable spectrum_settings()
{
    return {"spectrum",
            {{positional("kernel", "Kernel name or plugin file"),
              integer("dim", "", "Dimension D (1, 2 or 3)").mandatory(),
              number("k", "1", "k for kernels whose formula depends on it"), number("max", "50", "Largest kappa h"),
              integer("points", "500", "Intervals on [0, max]"), kernel_parameters(), plugin_files(), json_output()}}};
}

} // namespace sphkern
