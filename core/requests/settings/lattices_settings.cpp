#include "requests/settings/command_settings.hpp"

#include "requests/settings/shared_settings.hpp"

namespace sphkern {

SettingTable lattices_settings()
{
    return {"lattices",
            {{positional_list("lattice", "Lattice names or files to describe in full").command_line_only(),
              number("radius", "3", "Shells up to this radius, in d, when describing").command_line_only(),
              json_output(), plugin_files()}}};
}

} // namespace sphkern
