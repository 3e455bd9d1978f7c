// The inputs of a study in full, for results.json: the study file (bytes and SHA-256),
// each lattice's definition and each kernel's descriptor, so that a results file alone
// says what was computed (and `run --reproduce` can check that it still is).
#pragma once

#include "kernels/kernel.hpp"
#include "lattices/lattice.hpp"
#include "study/study.hpp"
#include "study/study_inputs.hpp"

#include <nlohmann/json_fwd.hpp>

namespace sphkern {

// {"label", "name", "source", "abi", "parameters": {name: value as used}, "file", "sha256",
//  "expression" (an expression kernel's file as read)}; "file" and "sha256" when the
//  source is a file (a blend names its parts in "source").
nlohmann::json kernel_input_json(const Kernel& kernel);

// {"name", "file", "sha256", "definition": the lattice file as read}.
nlohmann::json lattice_input_json(const Lattice& lattice);

// {"study": {"file", "sha256", "text"}, "kernels": [...], "lattices": [...]}.
nlohmann::json study_inputs_json(const Study& study, const StudyInputs& inputs);

} // namespace sphkern
