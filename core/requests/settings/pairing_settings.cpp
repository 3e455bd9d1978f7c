#include "requests/settings/command_settings.hpp"

#include "requests/settings/shared_settings.hpp"

#include "stability/dispersion.hpp"

namespace sphkern {

SettingTable pairing_settings()
{
    return {"pairing",
            {{kernel_name(), positional("lattice", "Lattice name or JSON file"), number("k", "", "One k (h = k d)"),
              code_choice()},
             code_parameters(),
             {number("kmin", "", "Smallest k of the range"), number("kmax", "", "Largest k of the range"),
              integer("samples", "1", "Evenly spaced k over [kmin, kmax]").counted(1, 1000),
              number("noise", "0.001", "Gaussian displacement per axis at the start, in units of d")
                  .within(0, 0.01, LowEnd::open, " (units of d; the motion starts linear)"),
              number("duration", "100", "Time of motion, in units of d / c")
                  .within(0, 1e4, LowEnd::open, " (units of d / c)"),
              number("damping", "0.1", "Velocity damping rate, in units of c / h")
                  .within(0, 100, LowEnd::closed, " (units of c / h)"),
              number("dt", "0.2", "Time step, in units of h / c").within(0, 0.5, LowEnd::open, " (units of h / c)"),
              number("gamma", "1.6666666666666667", "Adiabatic index of P = rho0 c^2 / gamma (rho / rho0)^gamma")
                  .within(min_gamma, 1e3, LowEnd::closed),
              number("horizon", "100", "Growth time (d/c) beyond which the linear verdict is weak"),
              integer("seed", "1", "Seed of the noise"),
              integer("threads", "0", "Threads (default: every core)").default_hidden().counted(0, 1024),
              kernel_parameters(), plugin_files(), json_output(), code_value()}}};
}

} // namespace sphkern
