// What `sphkern particles` shares between one source and a series of snapshots: its options
// and the measuring of one source.
#pragma once

#include "cli/code_options.hpp"
#include "cli/command.hpp"
#include "cli/source_options.hpp"
#include "requests/particles_request.hpp"
#include "support/io/output_targets.hpp"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace sphkern::cli {

struct ParticlesOptions : CommonOptions, SourceOptions {
    std::string kernel, gravity, volume, csv, vtk, plot, neighbours_by;
    bool bias_correction = false;
    std::vector<std::string> sets, more; // more: a series' further files or folders
    std::vector<double> h_over_l_range, nh_range, eta_range;
    double depth = 0, memory_limit = 0; // the defaults: requests/settings
    std::optional<double> h_over_l, eta, nh, k, support_per_h, rho0;
    SettingOptions codes; // --code and the codes' parameters but --eta (SWIFT's, with --code swift)
    int steps = 0, threads = 0;
    std::size_t histogram = 0;
    bool keep_going = false;
};

// A source measured: the set (a slab-measured snapshot's sample), the answer, the arguments.
struct Measured {
    ParticleSet set;
    ParticleAnswer answer;
    ParticleArguments arguments;
};

// A check of the set read, before it is measured.
using SetCheck = std::function<void(const ParticleSet&)>;

// `o.source` measured in memory or in slabs, its per-particle values written to `csv` and `vtk`
// (empty: not written); `outputs` are checked against the files the source reaches.
Measured measure_source(const ParticlesOptions& o, const Kernel& kernel, const std::vector<OutputTarget>& outputs,
                        const std::string& csv, const std::string& vtk, const SetCheck& check = {});

// The source and `o.more` (files and folders) as one run's series.
int measure_series(const ParticlesOptions& o, const Kernel& kernel);

} // namespace sphkern::cli
