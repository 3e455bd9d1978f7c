#include "requests/settings/command_settings.hpp"

#include "requests/settings/shared_settings.hpp"

namespace sphkern {

SettingTable block_settings()
{
    return {"block",
            {{kernel_name(), lattice_name(), number("k", "", "Smoothing coefficient, h = k d").mandatory(),
              list("size", "Cells along the basis vectors: N1,N2[,N3] (the last is vertical)").mandatory(),
              flag("periodic", "Periodic lateral sides (the top is always free)"),
              word("form", "sum", "Gradient form: sum, difference or monaghan"),
              integer("threads", "0", "Threads (default: every core)").default_hidden().counted(0, 1024),
              word("a_p", "voronoi", "Volume coefficient: a name or a positive number").as_option("--ap"),
              word("vtk", "", "Write per-particle results for ParaView: F.vtk legacy VTK, F.vtu VTK XML"),
              word("csv", "", "Write per-particle results as CSV"), kernel_parameters(), plugin_files(),
              json_output()}}};
}

} // namespace sphkern
