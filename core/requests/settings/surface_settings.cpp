#include "requests/settings/command_settings.hpp"

#include "requests/settings/shared_settings.hpp"

#include "analysis/surface_profile.hpp"

namespace sphkern {

SettingTable surface_settings()
{
    return {"surface",
            {{kernel_name(), lattice_name(),
              number("k", "", "Smoothing coefficient, h = k d (or --code and the code's setting)"), code_choice()},
             code_parameters(),
             {integer("layers", "4", "Report at least this many layers").counted(1, max_surface_layers),
              word("form", "sum", "Gradient form: sum, difference or monaghan"),
              word("a_p", "voronoi", "Volume coefficient: a name the lattice offers or a positive number")
                  .as_option("--ap"),
              list("gravity", "Gravity x,y[,z], normal to a lattice plane"),
              integer("site", "0", "Motif site on the top layer"),
              integer("termination", "",
                      "Which plane type is on top (an index from the listed terminations; default: --site's)"),
              kernel_parameters(), plugin_files(), json_output(), code_value()}}};
}

} // namespace sphkern
