// The "surface" section: a particle on each layer below a free surface normal to gravity,
// per lattice, kernel and gradient form (method.md section 6).
#pragma once

#include "analysis/surface_profile.hpp"
#include "study/sections/study_section.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace sphkern {

struct SurfaceCase {
    std::string lattice;
    std::string kernel_label;
    std::string form;
    std::string ap_name;
    double a_p = 0;
    double k = 0;
    SurfaceProfile profile;
};

struct SurfaceResults : SectionResults {
    std::vector<SurfaceCase> cases;

    nlohmann::json json(const Study& study) const override;
    std::string markdown(const Study& study) const override;
    void draw(const Study& study, Canvas& canvas) const override;
};

// {"k": a number or "best", "layers", "forms", "volume_coefficient"}.
std::shared_ptr<const StudySection> read_surface_section(const JsonNode& node, const std::filesystem::path& study_file);

} // namespace sphkern
