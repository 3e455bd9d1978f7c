// `sphkern run --reproduce results.json`: the study again from its results file alone,
// and whether the numbers agree.
#pragma once

#include "kernels/kernel_registry.hpp"
#include "study/study.hpp"

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace sphkern {

// The study a results file records ("study" as read, "study_file" for relative names);
// errors name the results file and the JSON path.
Study study_from_results(const nlohmann::json& recorded, const std::string& results_file);

// Inputs that are not what they were: a kernel or lattice file with another SHA-256 or
// definition, other parameter values, another study file. One line each.
std::vector<std::string> changed_inputs(const nlohmann::json& recorded, const nlohmann::json& now);

// Every number of the result sections (cases, comparison, surface, sweeps, stability)
// against the recorded ones, within a relative 1e-9 (absolute below 1): the
// differences, one line each (JSON Pointer, recorded, now), at most `limit`.
struct NumberComparison {
    std::size_t compared = 0;
    std::size_t differing = 0;
    std::vector<std::string> first;
};
NumberComparison compare_result_numbers(const nlohmann::json& recorded, const nlohmann::json& now, std::size_t limit);

// Runs the study a results file records and compares its numbers: whether all agree, and the
// text that says so (or the first differences). Inputs that changed are logged as warnings.
struct Reproduction {
    bool agreed = false;
    std::string text;
};
Reproduction reproduce_study(const std::string& results_file, KernelRegistry& registry);

} // namespace sphkern
