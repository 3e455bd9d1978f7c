// What every subcommand shares: how it registers, common options, and helpers to
// turn command-line text into kernels, lattices and numbers.
#pragma once

#include "analysis/hydrostatic_errors.hpp"
#include "kernels/kernel.hpp"
#include "kernels/kernel_registry.hpp"
#include "lattices/lattice.hpp"
#include "requests/evaluation_inputs.hpp"
#include "support/io/output_targets.hpp"
#include "support/text/value_checks.hpp"

#include "cli/options.hpp"
#include <nlohmann/json.hpp>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace sphkern::cli {

// A subcommand registers its options and returns the action to run if chosen.
using Action = std::function<int()>;

struct CommonOptions {
    std::vector<std::string> plugins; // --plugin FILE, repeatable
    bool json = false;
};

void add_plugin_option(Command command, CommonOptions& options);
void add_json_option(Command command, CommonOptions& options);

// --set NAME=VALUE pairs for kernel parameters.
void add_set_option(Command command, std::vector<std::string>& sets);
std::map<std::string, double> parse_sets(const std::vector<std::string>& sets);

KernelRegistry discover_kernels(const CommonOptions& options);
Kernel make_kernel(KernelRegistry& registry, const std::string& spec, const std::vector<std::string>& sets);

// What a command on one kernel and one lattice runs on: the lattice, then the kernel (the
// plugins discovered, --set applied), in that order, so that a bad lattice is said first.
struct KernelOnLattice {
    Lattice lattice;
    Kernel kernel;
};
KernelOnLattice kernel_on_lattice(const CommonOptions& options, const std::string& kernel, const std::string& lattice,
                                  const std::vector<std::string>& sets);

// The evaluation options shared by eps, roots and the commands after them.
struct EvaluationOptions {
    std::string ap;      // the defaults: requests/settings
    std::string gravity; // empty: the lattice's
    int site = 0;
    std::string shells; // explicit radii "1,1.732,2"
    bool continue_past_support = false;
};
void add_evaluation_options(Command command, EvaluationOptions& options);
// --ap, --gravity and --site alone (design, surface; their help is the command's own).
void add_point_options(Command command, EvaluationOptions& options);
// The options as numbers, for a request; the option names, for its errors.
EvaluationInputs evaluation_inputs(const EvaluationOptions& options);
EvaluationSources evaluation_sources(const EvaluationOptions& options);

// The output options a command was given (an option given as '' too, for the check to refuse).
std::vector<OutputTarget> given_outputs(const Command& command, const std::vector<OutputTarget>& options);
// The files a command reads, named on its command line: a source or lattice, a kernel file, plugins.
std::vector<std::string> read_inputs(const std::string& source, const std::string& kernel,
                                     const std::vector<std::string>& plugins);

// Prints a --json document to stdout, pretty and complete, with its "provenance" (an array:
// each element) and, when given, its "inputs" (command_inputs).
void print_json(nlohmann::json document, const nlohmann::json& inputs = nullptr);

// {"kernels": [descriptor], "lattices": [definition]} of a command's kernel and lattice
// (either may be null), as results.json records a study's.
nlohmann::json command_inputs(const Kernel* kernel, const Lattice* lattice);

Action add_kernels_command(Command app);
Action add_check_command(Command app);
Action add_lattices_command(Command app);
Action add_shells_command(Command app);
Action add_eps_command(Command app);
Action add_assess_command(Command app);
Action add_roots_command(Command app);
Action add_run_command(Command app);
Action add_surface_command(Command app);
Action add_block_command(Command app);
Action add_design_command(Command app);
Action add_stability_command(Command app);
Action add_spectrum_command(Command app);
Action add_particles_command(Command app);
Action add_relax_command(Command app);
Action add_pairing_command(Command app);
Action add_studies_command(Command app);

} // namespace sphkern::cli
