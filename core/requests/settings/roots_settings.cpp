#include "requests/settings/command_settings.hpp"

#include "requests/settings/shared_settings.hpp"

namespace sphkern {

SettingTable roots_settings()
{
    return {"roots",
            {{positional("kernel", "Kernel name or plugin file, or all"),
              positional("lattice", "Lattice name or file, or all (every shipped lattice)"),
              number("kmin", "0.75", "Smallest k"), number("kmax", "1.25", "Largest k"),
              number("epsilon", "0.01", "Tolerance of condition (22)"),
              flag("lateral", "Count the lateral gradient error in condition (22) too"),
              word("axis", "k", "The scale of --kmin/--kmax: k (h/d), h_over_l (h/V^(1/D)) or nh (neighbours)"),
              flag("stability",
                   "Also the stable k intervals of the window (linear stability) and where condition (22) holds there"),
              number("gamma", "1.6666666666666667", "With --stability: adiabatic index"),
              integer("steps", "100", "With --stability: k intervals of the scan").counted(1, max_scan_steps),
              integer("threads", "0", "With --stability: threads of the scan over k (default: every core)")
                  .default_hidden()
                  .counted(0, 1024),
              word("convention", "", "The old name of --code, kept as its alias"),
              word("code", "",
                   "Also give every k as an SPH code's own setting, with its own SPH density: swift, phantom, gadget2, "
                   "gadget4, pysph or dualsphysics"),
              number("horizon", "100",
                     "With --stability: growth time in d/c; slower instabilities count as stable (weak)"),
              word("h_model", "fixed",
                   "With --stability: fixed or adaptive h (h = (h/l) (m/rho)^(1/D), grad-h terms); k is the "
                   "equilibrium h = k d in both")},
             evaluation_settings(),
             {kernel_parameters(), plugin_files(), json_output()}}};
}

} // namespace sphkern
