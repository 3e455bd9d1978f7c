// What a study computes: the bulk cases (curves, roots, condition (22)), the comparison with
// a reference table, and what each optional section computed (its folder's results).
#pragma once

#include "analysis/acceptance.hpp"
#include "analysis/roots.hpp"
#include "analysis/site_roots.hpp"
#include "study/sections/study_section.hpp"

#include <nlohmann/json.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace sphkern {

// Why a root of a non-automatic mode differs from the default evaluation at that k.
struct ModeDifference {
    double radius; // shell radius in d
    int count;
    std::string reason;  // "evaluated past R" or "left out of the shell list"
    double q;            // r / h at the root
    double contribution; // to the function that vanished, in the mode (past R) or missing from it
};

struct RootExplanation {
    Root root;
    double default_value = 0;             // the same function in the default evaluation at root.k
    std::optional<double> default_root_k; // nearest root of the same function in the default evaluation
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
    std::string kernel; // name
    std::string kernel_label;
    double support = 0;
    std::string ap_name;
    double a_p = 0;
    double k_min = 0, k_max = 0; // the study's window, in k for this kernel, lattice and a_p
    std::vector<std::pair<double, ErrorValues>> curve;
    RootScan scan;                             // of the first site studied (the curve's site too)
    std::vector<int> sites;                    // the sites studied
    Acceptance acceptance;                     // condition (22) along gravity, at every site studied at once
    Acceptance acceptance_every;               // the same for every direction (the gradient-error tensor)
    std::vector<SiteRoots> per_site;           // each site on its own (lattices with several sites)
    std::vector<RootExplanation> explanations; // non-automatic modes only
};

enum class ComparisonStatus { reproduced, differs, erratum };
const char* status_name(ComparisonStatus status); // as in results.json

struct ComparisonRow {
    nlohmann::json reference; // the row as published
    std::string kernel;
    std::optional<ErrorFunction> function; // the error the row zeroes; empty: the paper finds no root
    std::optional<Root> computed;          // the matching root in the compared mode
    std::vector<std::string> compared;     // the values compared: "k", "eps_rho", "eps_gradp"
    std::vector<std::string> differing;    // those outside the tolerance ("roots": a root where none is printed)
    ComparisonStatus status = ComparisonStatus::differs;
    std::string note;
};

struct StudyResults {
    std::vector<StudyCase> cases;
    std::vector<ComparisonRow> comparison;
    std::vector<std::shared_ptr<const SectionResults>> sections; // [section_table()]: null where the study has none
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

// What the optional section of type T (a folder's results) computed, or nullptr.
template <class T>
const T* section_results(const StudyResults& results)
{
    for (const auto& s : results.sections)
        if (const auto* r = dynamic_cast<const T*>(s.get())) return r;
    return nullptr;
}

} // namespace sphkern
