#include "requests/settings/command_settings.hpp"

#include "requests/settings/shared_settings.hpp"

namespace sphkern {

SettingTable design_settings()
{
    return {"design",
            {{positional("kernel", "Kernel (a blend A+B, or one with parameters)"), lattice_name(),
              word("param", "", "The parameter to vary (alpha for a blend)").mandatory(),
              list("range", "Parameter range A B (default: blends [-1, 2], else the declared range)"),
              number("kmin", "0.75", "Smallest k"), number("kmax", "1.25", "Largest k"),
              integer("threads", "0", "Threads of the scan along the parameter (default: every core)")
                  .default_hidden()
                  .counted(0, 1024),
              word("a_p", "voronoi", "Volume coefficient: a name the lattice offers or a positive number")
                  .as_option("--ap"),
              list("gravity", "Gravity x,y[,z] (default: the lattice's)"), integer("site", "0", "Motif site"),
              kernel_parameters(), plugin_files(), json_output()}}};
}

} // namespace sphkern
