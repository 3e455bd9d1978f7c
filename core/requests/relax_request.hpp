// One relaxation (`sphkern relax`, a study source's "relax"): h, the settings and the g(r)
// that judges the glass, each value checked once and named as the front end names it.
#pragma once

#include "kernels/kernel.hpp"
#include "particles/formats/particle_writers.hpp"
#include "particles/particle_set.hpp"
#include "relax/relax_settings.hpp"
#include "requests/code_setting.hpp"
#include "requests/relax_report.hpp"
#include "requests/smoothing_request.hpp"

#include <nlohmann/json_fwd.hpp>

#include <array>
#include <cstddef>
#include <optional>
#include <string>

namespace sphkern {

struct RelaxSources {
    SmoothingSources smoothing;
    ValueSource method, steps, tolerance, gamma, dt, damping, alpha, max_move, threads, rdf_max, rdf_bins;
};
RelaxSources relax_sources(FrontEnd front_end);

// pressure or shift.
RelaxMethod relax_method_of(const std::string& name, const ValueSource& source);

// Steps 1 to 1e7, tolerance [0, 1], gamma (0, 1000], dt (0, 0.5], damping [0, 100], alpha
// (0, 10], max_move (0, 0.5], threads 0 to 1024.
void check_relax_settings(const RelaxSettings& settings, const RelaxSources& sources);

// g(r) up to r_max mean spacings (above 0.5) in 1 to 100000 bins.
void check_rdf(double r_max, std::size_t bins, const RelaxSources& sources);

// The set a run made, judged: the particle measures at its h (uniform volumes, statistics
// only), g(r) up to r_max mean spacings in `bins`, and a Poisson set's RMS e0 at the same h.
RelaxedSet judge_relaxed(const Kernel& kernel, const RelaxResult& run, int threads, double r_max, std::size_t bins);

// The code a relaxed set is written for (`relax --code`): named alone, the file is in its
// layout with its stored h at the run's one h; with its parameter, the run's h is the code's
// at the set's rest density (m / rho = V), and each written h is the particle's own as the
// code solves it (with its SPH density for SWIFT, Phantom and GADGET).
struct RelaxCode {
    std::string name;
    std::optional<double> value;
};

// A code whose parameter is given sets h: no other rule for h beside it (h_given: h_over_l, nh
// or k), named as the front end names them.
void check_code_beside_h(const RelaxCode& code, bool h_given, FrontEnd front_end, const CodeSettingSources& sources);

// A code, a value its parameter can take, a kernel it ships; named alone only beside an
// output (empty: none); an output other than .csv only for the codes whose initial conditions
// sphkern writes (the codes with a layout: HDF5, or Phantom's dump), and a name the code opens
// (GADGET and PySPH: .hdf5; or .csv).
void check_relax_code(const RelaxCode& code, const std::string& output, const Kernel& kernel, int dimension,
                      const CodeSettingSources& sources);

// The layout an output other than .csv is written in: SWIFT's without a code, a Phantom full
// dump for phantom.
ParticleLayout relax_layout(const std::optional<RelaxCode>& code);

// The run's h of a code's parameter: h = c V^(1/D), sphkern's eta = c.
SmoothingSpec relax_code_smoothing(const RelaxCode& code, const Kernel& kernel, int dimension,
                                   const CodeSettingSources& sources);

// What the initial conditions hold beside positions and h: the density rho0 (masses rho0 V,
// V the mean volume) and the internal energy u, by default that of an ideal gas whose sound
// speed is the relaxation's c = 1, u = c^2 / (gamma (gamma - 1)) (0 where gamma <= 1: no
// ideal gas has that sound speed).
struct InitialState {
    double eos_gamma = 5.0 / 3;
    double rho0 = 1;
    std::optional<double> u;
};

// The relaxed set as initial conditions (InitialState). Without a code: SWIFT's layout for its own kernels, h = H /
// gamma with SWIFT's gamma and the kernel's name, and sphkern's h and R for a kernel SWIFT lacks. With a code: its
// layout and its stored h (code_support_per_h), solved per particle on the run's set (each copy takes the original's)
// where the code's parameter is given and the code solves h with its density. `written`: the run's set, or copies of it
// side by side (tiled_set).
ParticleOutput initial_conditions(const Kernel& kernel, const ParticleSet& written, const RelaxResult& run,
                                  const InitialState& state, const std::optional<RelaxCode>& code, int threads);

// {"name", "parameter", "value" (if given), "layout", "written_h": "sph_density" or "run_h"}
// and its line.
nlohmann::json relax_code_json(const RelaxCode& code);
std::string relax_code_text(const RelaxCode& code);

// Copies of the relaxed set side by side along each edge of its box ("2,2,2"): whole numbers
// 1 to 1000, as many as the set's dimensions and within the memory budget (else exit 3), and
// one copy for an empty text.
// A name the relaxed set can be written to (.h5, .hdf5 or .csv; for Phantom any name but .h5
// and .hdf5, a full dump unless it ends in .csv), named as the front end names it.
void check_relax_output(const std::string& file, const ValueSource& source, const std::optional<RelaxCode>& code);

std::array<int, 3> tiles_of(const std::string& text, const ParticleSet& set, const ValueSource& source);

// The one h of a relaxation (fixed-h SPH; a file's own h is not used): the set must have a
// periodic box and fit the spec (smoothing_spec's).
double relax_h(const SmoothingSpec& spec, const ParticleSet& set, const Kernel& kernel,
               const SmoothingSources& sources);

} // namespace sphkern
