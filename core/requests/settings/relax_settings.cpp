#include "requests/settings/command_settings.hpp"

#include "requests/settings/shared_settings.hpp"

namespace sphkern {

SettingTable relax_settings()
{
    return {
        "relax",
        {{kernel_name().in_study("/kernel"),
          positional("source", "A lattice (name or file), poisson, or a particle file (.h5/.hdf5, .csv, .vtk, a GADGET "
                               "binary snapshot, a Phantom dump)")},
         source_settings(),
         {h_over_l_setting("h over the mean spacing l = V^(1/D), sphkern's own (default 1.2)").in_study("/h_over_l"),
          number("eta", "", "With --code swift: SWIFT's eta, h = eta (m / rho)^(1/D)").command_line_only(),
          nh_setting().in_study("/nh"), number("k", "", "Lattice: h = k d"),
          word("code", "",
               "The code --output is for: swift, gadget2, gadget4, pysph or phantom (a full dump), its layout and h; "
               "with its parameter (--eta for swift), the run's h and each written h as the code sets it")},
         code_parameters({"eta", "particle_radius"}),
         {word("method", "pressure", "pressure (SPH pressure force with damping) or shift (particle shifting)")
              .in_study("/method"),
          integer("steps", "200", "At most this many steps").counted(1, 10000000).in_study("/steps"),
          number("tolerance", "0", "Stop once a step's RMS move is below this many h (0: never)")
              .within(0, 1, LowEnd::closed, " (units of h per step)"),
          number("gamma", "1.6666666666666667", "pressure: adiabatic index of P = rho0 c^2 / gamma (rho / rho0)^gamma")
              .within(0, 1e3, LowEnd::open),
          // Kick-drift-kick is stable for omega dt < 2; the fastest SPH sound waves have omega ~ 2 c / h.
          number("dt", "0.2", "pressure: time step in units of h / c")
              .within(0, 0.5, LowEnd::open, " (units of h / c)"),
          number("damping", "0.5", "pressure: velocity damping rate in units of c / h")
              .within(0, 100, LowEnd::closed, " (units of c / h)"),
          number("alpha", "0.1", "shift: dx = -alpha h^2 sum_j V_j grad W_ij").within(0, 10, LowEnd::open),
          number("max_move", "0.1", "shift: largest move of a step, in units of h")
              .within(0, 0.5, LowEnd::open, " (units of h)"),
          integer("threads", "0", "Threads (default: every core)").default_hidden().counted(0, 1024),
          number("rdf_max", "3", "g(r) up to this many mean spacings"), integer("rdf_bins", "60", "g(r) bins"),
          number("memory_limit", "0", "Memory budget in GiB (default: three quarters of the available memory)")
              .default_hidden(),
          word("output", "",
               "Write the relaxed set: .h5/.hdf5 (SWIFT's layout, or --code's), .csv, or with --code phantom any other "
               "name (a Phantom full dump, NAME_00000.tmp)"),
          number("rho0", "", "With --output: the density written, masses rho0 V (default 1)"),
          number("u", "",
                 "With an HDF5 or Phantom --output: the internal energy written (default c^2 / (gamma (gamma - 1)), "
                 "0.9 for gamma 5/3)"),
          list("tile",
               "With --output: write N1,N2[,N3] copies of the relaxed set side by side, in a box as many times larger"),
          word("history", "",
               "Write the history of the run: F.csv its steps as CSV, F.pvd the particles at every step as a ParaView "
               "series (F_k.vtu beside F.pvd)"),
          kernel_parameters(), plugin_files(), json_output(), code_value()}}};
}

} // namespace sphkern
