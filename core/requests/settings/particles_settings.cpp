#include "requests/settings/command_settings.hpp"

#include "requests/settings/shared_settings.hpp"

namespace sphkern {

SettingTable particles_settings()
{
    return {
        "particles",
        {{kernel_name(),
          positional("source", "A lattice (name or file), poisson, or a particle file (.h5/.hdf5, .csv, .vtk, a GADGET "
                               "binary snapshot, a Phantom dump)")
              .command_line_only(),
          positional_list("more", "Further snapshots of the run: the files (or folders) are measured as a series, "
                                  "ordered by the times in their headers")
              .command_line_only()},
         // Python takes positions and a box, not a source to make.
         except_in_python(source_settings(), {"box"}),
         {flag("keep_going", "Series: report a snapshot that fails and go on with the rest"),
          word("plot", "", "Series: draw the errors against time (median, p1 to p99) as .svg, .png or .pdf"),
          h_over_l_setting("h over the mean spacing l = V^(1/D), sphkern's own (default 1.2 without a file h)"),
          number("eta", "", "With --code swift: SWIFT's eta, h = eta (m / rho)^(1/D)").command_line_only(),
          nh_setting(), number("k", "", "Lattice: h = k d").command_line_only(),
          word("code", "",
               "h as an SPH code sets it, from each particle's SPH density where the code solves for it: swift "
               "(--eta), phantom (--hfact), gadget2 or gadget4 (--nngb), pysph (--hdx), dualsphysics (--coefh); "
               "without its parameter, a file's h as the code stores it")},
         code_parameters({"eta", "particle_radius"}),
         {word("neighbours_by", "",
               "With --code: what its density solve counts, number or mass (default the code's; SWIFT's "
               "use_mass_weighted_num_ngb is mass)"),
          flag("bias_correction", "With --code: the density bias the code subtracts when built so (gadget4: "
                                  "WENDLAND_BIAS_CORRECTION, Wendland kernels in 3D)"),
          number("support_per_h", "", "File h: the support radius over the stored h (GADGET 1, SWIFT gamma, PySPH R)"),
          list("h_over_l_range", "Sweep h / l over [A, B]"),
          list("eta_range", "The old name of --h-over-l-range (refused, naming it)").old_name(),
          list("nh_range", "Sweep N_H over [A, B]"),
          integer("steps", "10", "Sweep: steps between A and B").counted(1, 1000),
          word("volume", "", "uniform (box / N), file (m / rho) or voronoi (default: file if m and rho, else uniform)"),
          list("gravity", "Direction of eps_gradp, x,y[,z] (default: the lattice's, else -y or -z)"),
          number("depth", "1", "Depth of the sum form's eps_gradp_sum, in units of h")
              .within(0, 1e6, LowEnd::closed, " (units of h)"),
          number("rho0", "", "Reference density of eps_rho (default: the set's total mass over its volume)"),
          integer("histogram", "0", "Histogram bins of e0, eps_rho, eps_gradp and eps_gradp_sum")
              .default_hidden()
              .counted(0, 100000),
          integer("threads", "0", "Threads (default: every core)").default_hidden().counted(0, 1024),
          number("memory_limit", "0", "Memory budget in GiB (default: three quarters of the available memory)")
              .default_hidden()
              .command_line_only(),
          word("csv", "", "Write one row per particle as CSV").command_line_only(),
          word("vtk", "", "Write the per-particle values for ParaView: F.vtk legacy VTK, F.vtu VTK XML")
              .command_line_only(),
          kernel_parameters(),
          plugin_files(),
          json_output(),
          positional("positions", "The positions, shape (N, 2) or (N, 3); or a particle file, or a run's files")
              .python_only(),
          list("h", "The smoothing lengths, one number or one per particle, as stored").python_only(),
          code_value(),
          list("masses", "The masses, one number or one per particle").python_only(),
          list("densities", "The densities, one number or one per particle").python_only()}}};
}

} // namespace sphkern
