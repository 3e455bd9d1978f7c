// The sections of a study, each run on its own into the study's results from inputs
// resolved before any of them (study_inputs.hpp): the bulk cases first (the others find
// theirs by CaseKey for condition (22)), then the optional ones.
#pragma once

#include "study/study.hpp"
#include "study/study_inputs.hpp"
#include "study/study_results.hpp"

namespace sphkern {

// Every kernel x lattice x a_p x mode: curves, roots, jumps, condition (22), explanations.
void run_bulk_section(const Study& study, const StudyInputs& inputs, StudyResults& results);

// "surface": a free-surface profile per lattice, kernel and gradient form.
void run_surface_section(const Study& study, const StudyInputs& inputs, StudyResults& results);

// "sweeps": both errors over (k, parameter) and the designed kernels.
void run_sweep_section(const Study& study, const StudyInputs& inputs, StudyResults& results);

// "stability": stable k intervals, dispersion curves and their overlap with condition (22).
void run_stability_section(const Study& study, const StudyInputs& inputs, StudyResults& results);

// "particles": every kernel on particle sets that are no lattice, over N_H or eta.
void run_particles_section(const Study& study, const StudyInputs& inputs, StudyResults& results);

} // namespace sphkern
