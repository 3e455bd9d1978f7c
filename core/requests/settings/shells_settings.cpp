#include "requests/settings/command_settings.hpp"

#include "requests/settings/shared_settings.hpp"

namespace sphkern {

SettingTable shells_settings()
{
    return {"shells",
            {{lattice_name(), number("radius", "", "Largest radius, in units of d").mandatory(),
              integer("site", "0", "Motif site"), list("gravity", "Direction for the moments (default: the lattice's)"),
              json_output(), plugin_files()}}};
}

} // namespace sphkern
