// An optional section of a study ("surface", "sweeps", "stability", "particles"): what it
// reads from the study file, how its work is bounded, what it resolves before any section
// runs, how it runs after the bulk cases, and how what it computed is written to
// results.json, reported and plotted all live in the section's own folder beside this
// file. The study's spine walks the table of sections (section_table.hpp) at each step.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <functional>
#include <memory>
#include <string>

namespace sphkern {

struct Study;
struct StudyInputs;
struct StudyResults;
struct Canvas;
class JsonNode;
class KernelRegistry;

// What a section computed.
class SectionResults {
public:
    virtual ~SectionResults() = default;
    virtual nlohmann::json json(const Study& study) const = 0;       // its entry in results.json
    virtual std::string markdown(const Study& study) const = 0;      // its part of the report
    virtual void draw(const Study& study, Canvas& canvas) const = 0; // its figures
};

// A section with its inputs resolved and checked: run after the bulk cases, which it may read.
using SectionRun = std::function<std::shared_ptr<const SectionResults>(const Study& study, const StudyInputs& inputs,
                                                                       const StudyResults& bulk)>;

// A section as the study file gives it.
class StudySection {
public:
    virtual ~StudySection() = default;
    // Refuses work beyond the section's budget (Error(input) naming `root`), before anything is loaded.
    virtual void check_budget(const Study& study, const JsonNode& root) const = 0;
    // Loads and checks what the section needs beyond the study's kernels, lattices and a_p
    // (it may add windows to `inputs`); nothing is computed before every section is resolved.
    virtual SectionRun resolve(const Study& study, KernelRegistry& registry, StudyInputs& inputs) const = 0;
};

} // namespace sphkern
