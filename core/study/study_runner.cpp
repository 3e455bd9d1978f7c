#include "study/study_runner.hpp"

#include "study/bulk_section.hpp"
#include "study/reference_comparison.hpp"
#include "study/study_inputs.hpp"
#include "study/study_provenance.hpp"

namespace sphkern {

StudyResults run_study(const Study& study, KernelRegistry& registry)
{
    const StudyInputs inputs = load_study_inputs(study, registry);
    StudyResults results;
    results.inputs = study_inputs_json(study, inputs);
    run_bulk_section(study, inputs, results);
    for (const auto& section : inputs.sections)
        results.sections.push_back(section ? section(study, inputs, results) : nullptr);
    if (inputs.reference) compare_with_reference(*inputs.reference, results);
    return results;
}

} // namespace sphkern
