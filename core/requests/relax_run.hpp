// One relaxation as every front end runs it (`sphkern relax`, sphkern.relax): the settings
// checked before anything is read, then the set's h, the run (each step to a ParaView series
// or the steps to a CSV history), the glass judged and the relaxed set written.
#pragma once

#include "kernels/kernel.hpp"
#include "particles/particle_set.hpp"
#include "requests/relax_output.hpp"
#include "requests/relax_request.hpp"

#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace sphkern {

// What a front end gave, in the request's words; empty strings and nullopt: not given.
struct RelaxGiven {
    std::optional<double> h_over_l, nh, k;
    std::optional<RelaxCode> code;
    CodeSettingSources code_sources; // how the front end names the code and its parameter
    std::string method;
    RelaxSettings settings;
    double rdf_max = 0;
    std::size_t rdf_bins = 0;
    std::optional<std::string> output, history; // given, even empty (refused as a name)
    std::string tile;
    std::optional<double> rho0, u;
    bool primitive_block = false; // a lattice block cut from its primitive cell (the output's box hint)
};

// A relaxation checked: its settings, its rule for h and its outputs, as the front end named them.
struct RelaxJob {
    FrontEnd front_end = FrontEnd::command_line;
    RelaxGiven given;
    SmoothingSpec spec;
    RelaxOutput output;  // empty file: none
    std::string history; // empty: none
};

// Every check that needs no file read, in the order a user meets them; the files to be
// written none of `inputs` (the files read: a source, a kernel file, plugins).
RelaxJob relax_job(RelaxGiven given, FrontEnd front_end, const std::vector<std::string>& inputs);

struct RelaxOutcome {
    RelaxResult run;
    RelaxedSet judged;
    std::optional<WrittenSet> written;
};

// The run on the loaded set; the set's linked files are checked against the outputs first.
RelaxOutcome run_relax(const Kernel& kernel, ParticleSet set, const RelaxJob& job);

// relax's --json document (without provenance) and its text report.
nlohmann::json relax_outcome_json(const Kernel& kernel, const RelaxJob& job, const RelaxOutcome& outcome);
void print_relax_outcome(std::FILE* out, const Kernel& kernel, const RelaxJob& job, const RelaxOutcome& outcome);

} // namespace sphkern
