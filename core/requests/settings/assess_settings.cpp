#include "requests/settings/command_settings.hpp"

#include "requests/settings/shared_settings.hpp"

namespace sphkern {

SettingTable assess_settings()
{
    return {
        "assess",
        {{kernel_name(),
          positional("lattice", "Lattice name or file, or a particle file (.h5/.hdf5, .csv, .vtk, a GADGET binary "
                                "snapshot, a Phantom dump)"),
          number("k", "", "Smoothing coefficient, h = k d (or --code and the code's own setting)"), code_choice()},
         code_parameters(),
         {number("kmin", "0.75", "The window of the recommended setting: smallest k"),
          number("kmax", "2", "Largest k of the window"), number("epsilon", "0.01", "Tolerance of condition (22)"),
          number("gamma", "1.6666666666666667", "Adiabatic index of the stability analysis"),
          number("coef_sound", "",
                 "With a weakly compressible code (dualsphysics, pysph): its sound speed over sqrt(g H), whose "
                 "hydrostatic pressure at rest, up to rho c^2 / coef^2, the stability assumes (default the code's: 20, "
                 "10 sqrt(2))"),
          number("horizon", "100", "Growth time in d/c; slower instabilities count as weak"),
          integer("glass", "0",
                  "Also relax a glass of this many particles at the recommended setting and measure it there (100 to "
                  "10^5; default none)")
              .default_hidden()},
         evaluation_settings(),
         {list("box", "Particle file: a periodic box Lx,Ly[,Lz] from the origin"),
          word("array", "", "PySPH file: the particle array, or several (the first is measured)")},
         parameter_ranges(),
         {integer("steps", "10", "Particle file: steps of a parameter's sweep"),
          integer("threads", "0",
                  "Threads of a particle file's sums, or of a lattice's stability scan over k (default: every core)")
              .default_hidden()
              .counted(0, 1024),
          word("neighbours_by", "",
               "Particle file: what the code's density solve counts, number or mass (default the code's)"),
          flag("bias_correction",
               "Particle file: the density bias the code subtracts when built so (gadget4: WENDLAND_BIAS_CORRECTION)"),
          kernel_parameters(), plugin_files(), json_output(), code_value()}}};
}

} // namespace sphkern
