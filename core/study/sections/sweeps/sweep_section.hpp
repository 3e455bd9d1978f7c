// The "sweeps" section: both errors over (k, parameter) for a kernel with a free parameter,
// and the kernels designed where both vanish (sphkern design).
#pragma once

#include "analysis/acceptance.hpp"
#include "analysis/design.hpp"
#include "study/sections/study_section.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace sphkern {

struct SweepCase {
    std::string lattice;
    std::string kernel;
    std::string parameter;
    std::string ap_name;
    double a_p = 0;
    std::vector<double> ks, values;              // the grid
    std::vector<std::vector<double>> rho, gradp; // [value index][k index]
    DesignResult design;
    std::vector<Acceptance> designed_acceptance; // condition (22) of each designed kernel
};

struct SweepResults : SectionResults {
    std::vector<SweepCase> cases;

    nlohmann::json json(const Study& study) const override;
    std::string markdown(const Study& study) const override;
    void draw(const Study& study, Canvas& canvas) const override;
};

// [{"kernel", "set", "parameter", "range": [min, max], "samples"}, ...]; a kernel file beside the study.
std::shared_ptr<const StudySection> read_sweep_section(const JsonNode& node, const std::filesystem::path& study_file);

} // namespace sphkern
