#include "requests/settings/command_settings.hpp"

#include "requests/settings/shared_settings.hpp"

namespace sphkern {

SettingTable spectrum_settings()
{
    return {"spectrum",
            {{kernel_name(), integer("dim", "", "Dimension D (1, 2 or 3)").mandatory().counted(1, 3),
              number("k", "1", "k for kernels whose formula depends on it").counted(1e-3, 100),
              number("max", "50", "Largest kappa h").counted(0.1, 1000),
              integer("points", "500", "Intervals on [0, max]").counted(1, 100000), kernel_parameters(), plugin_files(),
              json_output()}}};
}

} // namespace sphkern
