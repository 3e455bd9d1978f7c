// A study's inputs, resolved and checked once before any section computes: its kernels and
// lattices loaded, each lattice's a_p and sites, each mode's evaluation per kernel, the
// windows in k, what each optional section needs (its own resolve) and the reference table
// matched to the cases. Errors name the study file and the JSON Pointer of the entry at fault.
#pragma once

#include "analysis/hydrostatic_errors.hpp"
#include "kernels/kernel_registry.hpp"
#include "lattices/lattice.hpp"
#include "study/study.hpp"

#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace sphkern {

struct StudyInputs {
    std::vector<Kernel> kernels; // in the study's order
    std::vector<Lattice> lattices;
    std::vector<std::vector<double>> a_p;                // [lattice][volume coefficient]
    std::vector<std::vector<int>> sites;                 // [lattice]: the sites studied
    std::vector<std::vector<EvaluationMode>> evaluation; // [mode][kernel]
    std::vector<SectionRun> sections;                    // [section_table()]: empty where the study has none
    std::optional<ReferenceTable> reference;             // matched to the study's cases
    std::vector<std::string> parts; // "accuracy", then each section's key the study has, in the order they run

    // The study's window in k for kernel `kernel` (an index into `kernels`) on lattice
    // `lattice`, at a site and a_p, as resolve_window worked it out.
    std::pair<double, double> window(std::size_t lattice, std::size_t kernel, int site, double a_p) const;

    using WindowKey = std::tuple<std::size_t, std::size_t, int, double>; // lattice, kernel, site, a_p
    std::map<WindowKey, std::pair<double, double>> windows;              // every window the sections use
};

// What a part's progress estimate covers: " in this part (2 of 3), then particles" (the parts
// to come are named, not timed: their cost is not known until they run).
std::string part_scope(const StudyInputs& inputs, const std::string& part);

// Loads and checks every input; nothing is computed before this returns.
StudyInputs load_study_inputs(const Study& study, KernelRegistry& registry);

// The study's window in k for `kernel` on `lattice` at a site and a_p (Error naming "/k").
std::pair<double, double> study_window(const Study& study, const Kernel& kernel, const Lattice& lattice, int site,
                                       double a_p);

// Works out the window StudyInputs::window gives for these indices, once.
void resolve_window(const Study& study, StudyInputs& inputs, std::size_t lattice, std::size_t kernel, int site,
                    double a_p);

// The index of the first automatic mode, the one whose condition (22) the stability and
// surface sections read; empty if every mode has fixed shells.
std::optional<std::size_t> first_automatic_mode(const Study& study);

} // namespace sphkern
