#include "study/study_runner.hpp"

#include "study/reference_comparison.hpp"
#include "study/sections/sections.hpp"
#include "study/study_inputs.hpp"
#include "study/study_provenance.hpp"

namespace sphkern {

StudyResults run_study(const Study& study, KernelRegistry& registry)
{
    const StudyInputs inputs = load_study_inputs(study, registry);
    StudyResults results;
    results.inputs = study_inputs_json(study, inputs);
    run_bulk_section(study, inputs, results);
    run_surface_section(study, inputs, results);
    run_sweep_section(study, inputs, results);
    run_stability_section(study, inputs, results);
    run_particles_section(study, inputs, results);
    if (inputs.reference) compare_with_reference(*inputs.reference, results);
    return results;
}

} // namespace sphkern
