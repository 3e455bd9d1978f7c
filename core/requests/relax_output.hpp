// What a relaxation writes besides its results, for every front end: the relaxed set (tiled)
// as initial conditions, and the history of a run that diverged.
#pragma once

#include "kernels/kernel.hpp"
#include "relax/relaxation.hpp"
#include "requests/relax_request.hpp"
#include "support/text/value_checks.hpp"

#include <nlohmann/json_fwd.hpp>

#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace sphkern {

// The file the relaxed set is written to (empty: none), the copies of it side by side
// ("N1,N2[,N3]"; empty: one) and what the initial conditions hold besides positions.
struct RelaxOutput {
    std::string file, tile;
    std::optional<double> rho0, u;
};

// rho0, u (positive) and tile only beside a file, u not in a .csv (which holds m, not u);
// named as the front end names them.
void check_relax_output_settings(const RelaxOutput& output, FrontEnd front_end);

// The set written (tiled), its initial conditions at the run's settings and the code's h.
struct WrittenSet {
    std::string file, layout; // the absolute path; "CSV", "SWIFT HDF5", ...
    std::size_t particles = 0;
};
// "wrote F: N particles, L layout" and {"file", "particles", "layout"}.
std::string written_text(const WrittenSet& written);
nlohmann::json written_json(const WrittenSet& written);
WrittenSet write_relaxed_set(const Kernel& kernel, const RelaxResult& run, const RelaxOutput& output,
                             const RelaxSettings& settings, const std::optional<RelaxCode>& code,
                             const std::array<int, 3>& tiles);

// relax_particles; where the run diverges and `history` names a file, the steps before it
// (all finite) go there by write_history, and the error says so. The set itself is not
// written: its positions are what diverged.
RelaxResult relax_until_diverged(const Kernel& kernel, ParticleSet set, double h, const RelaxSettings& settings,
                                 const std::function<void(const RelaxState&, const RelaxStep&)>& observe,
                                 const std::string& history,
                                 const std::function<void(const std::vector<RelaxStep>&)>& write_history);

} // namespace sphkern
