// What a study computes, section by section: the bulk cases (curves, roots, condition
// (22)), the comparison with a reference table, free-surface profiles, parameter sweeps
// and linear stability.
#pragma once

#include "analysis/acceptance.hpp"
#include "analysis/design.hpp"
#include "analysis/roots.hpp"
#include "analysis/site_roots.hpp"
#include "analysis/surface_profile.hpp"
#include "stability/dispersion_path.hpp"
#include "stability/recommended_k.hpp"
#include "stability/stability_over_k.hpp"
#include "study/study_particles.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace sphkern {

// Why a root of a non-automatic mode differs from the default evaluation at that k.
struct ModeDifference {
    double radius;      // shell radius in d
    int count;
    std::string reason; // "evaluated past R" or "left out of the shell list"
    double q;           // r / h at the root
    double contribution; // to the function that vanished, in the mode (past R) or missing from it
};

struct RootExplanation {
    Root root;
    double default_value = 0;              // the same function in the default evaluation at root.k
    std::optional<double> default_root_k;  // nearest root of the same function in the default evaluation
    std::vector<ModeDifference> differences;
};

// Where a bulk case stands in its study: indices into the study's lattices, kernels,
// volume coefficients and modes. Sections find each other's cases by it.
struct CaseKey {
    std::size_t lattice = 0, kernel = 0, volume_coefficient = 0, mode = 0;
    bool operator==(const CaseKey&) const = default;
};

struct StudyCase {
    CaseKey key;
    std::string lattice;
    int dimension = 0;
    std::string mode;
    bool automatic = true;
    std::string kernel;      // name
    std::string kernel_label;
    double support = 0;
    std::string ap_name;
    double a_p = 0;
    double k_min = 0, k_max = 0; // the study's window, in k for this kernel, lattice and a_p
    std::vector<std::pair<double, ErrorValues>> curve;
    RootScan scan;                      // of the first site studied (the curve's site too)
    std::vector<int> sites;             // the sites studied
    Acceptance acceptance;              // condition (22) along gravity, at every site studied at once
    Acceptance acceptance_every;        // the same for every direction (the gradient-error tensor)
    std::vector<SiteRoots> per_site;    // each site on its own (lattices with several sites)
    std::vector<RootExplanation> explanations; // non-automatic modes only
};

enum class ComparisonStatus { reproduced, differs, erratum };
const char* status_name(ComparisonStatus status); // as in results.json

struct ComparisonRow {
    nlohmann::json reference;              // the row as published
    std::string kernel;
    std::optional<ErrorFunction> function; // the error the row zeroes; empty: the paper finds no root
    std::optional<Root> computed;          // the matching root in the compared mode
    std::vector<std::string> compared;      // the values compared: "k", "eps_rho", "eps_gradp"
    std::vector<std::string> differing;     // those outside the tolerance ("roots": a root where none is printed)
    ComparisonStatus status = ComparisonStatus::differs;
    std::string note;
};

struct SurfaceCase {
    std::string lattice;
    std::string kernel_label;
    std::string form;
    std::string ap_name;
    double a_p = 0;
    double k = 0;
    SurfaceProfile profile;
};

struct SweepCase {
    std::string lattice;
    std::string kernel;
    std::string parameter;
    std::string ap_name;
    double a_p = 0;
    std::vector<double> ks, values;                 // the grid
    std::vector<std::vector<double>> rho, gradp;    // [value index][k index]
    DesignResult design;
    std::vector<Acceptance> designed_acceptance;    // condition (22) of each designed kernel
};

// Where the accurate k (condition (22), one a_p, the first automatic mode) are stable too.
struct StabilityOverlap {
    std::string ap_name;
    std::vector<KInterval> accurate, both;
    RecommendedK recommended; // the centre of the widest of `both`
    std::vector<double> in_conventions; // the recommended k in each of code_conventions(), when found
};

struct StabilityCase {
    std::string lattice;
    std::string kernel_label;
    double gamma = 0;
    std::string h_model = "fixed";
    std::optional<std::string> refused; // why the lattice has no dispersion matrix; empty when it has one
    StabilityOverK over_k;
    double path_k = 0;        // where the dispersion curves are drawn
    DispersionPath path;
    std::vector<StabilityOverlap> overlap;
};

struct StudyResults {
    std::vector<StudyCase> cases;
    std::vector<ComparisonRow> comparison;
    std::vector<SurfaceCase> surface;
    std::vector<SweepCase> sweeps;
    std::vector<StabilityCase> stability;
    std::vector<ParticlesCase> particles;
    double tolerance = 1e-4;
    nlohmann::json reference; // the whole reference table, if any
    nlohmann::json inputs;    // the study file, lattices and kernels in full (study_provenance.hpp)
};

// The bulk case at `key`, or nullptr.
inline const StudyCase* find_case(const StudyResults& results, const CaseKey& key)
{
    for (const auto& c : results.cases)
        if (c.key == key) return &c;
    return nullptr;
}

} // namespace sphkern
