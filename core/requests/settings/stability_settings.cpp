#include "requests/settings/command_settings.hpp"

#include "requests/settings/shared_settings.hpp"

namespace sphkern {

SettingTable stability_settings()
{
    return {"stability",
            {{kernel_name(), lattice_name(), number("k", "", "Smoothing coefficient, h = k d"),
              number("kmin", "", "Scan k from here (with --kmax): stable intervals"),
              number("kmax", "", "Scan k up to here"),
              integer("steps", "50", "Intervals of the k scan").counted(1, max_scan_steps).in_study("/k/steps"),
              number("gamma", "1.6666666666666667", "Adiabatic index of P = rho c^2 / gamma"),
              list("wavevector", "Cartesian wave vector x,y[,z] in 1/d: the modes there"),
              integer("path", "0", "Dispersion curves along the high-symmetry path: about this many points")
                  .default_hidden()
                  .counted(2, 100000)
                  .in_study("/path_points"),
              integer("grid", "0",
                      "First zone grid, points per reciprocal axis (default 8 in 3D, 32 in 2D; doubled until the "
                      "minimum settles)")
                  .default_hidden()
                  .counted(2, 400)
                  .in_study("/grid"),
              number("horizon", "100", "Growth time in d/c: slower instabilities are weak").in_study("/horizon"),
              word("h_model", "fixed",
                   "Smoothing length: fixed (h = k d) or adaptive (h = eta (m/rho)^(1/D) with grad-h terms; k sets the "
                   "equilibrium h = k d)")
                  .in_study("/h_model"),
              integer("threads", "0", "Threads (default: every core)").default_hidden().counted(0, 1024),
              word("code", "",
                   "With --kmin/--kmax: the stable intervals also in an SPH code's own setting, with its own density: "
                   "swift, phantom, gadget2, gadget4, pysph or dualsphysics"),
              kernel_parameters(), plugin_files(), json_output()}}};
}

} // namespace sphkern
