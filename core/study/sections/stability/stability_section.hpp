// The "stability" section: per kernel and lattice, min omega^2 against k and the stable k
// intervals, the dispersion curves along the high-symmetry path, and where the stable k
// meet condition (22) with the k recommended there.
#pragma once

#include "analysis/acceptance.hpp"
#include "stability/dispersion_path.hpp"
#include "stability/recommended_k.hpp"
#include "stability/stability_over_k.hpp"
#include "study/sections/study_section.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sphkern {

// Where the accurate k (condition (22), one a_p, the first automatic mode) are stable too.
struct StabilityOverlap {
    std::string ap_name;
    std::vector<KInterval> accurate, both;
    RecommendedK recommended; // the centre of the widest of `both`
    // The recommended k in each code's own setting (study_codes(), with the lattice's SPH density
    // at the site), when found; NaN for a code that does not ship the kernel.
    std::vector<double> in_codes;
};

struct StabilityCase {
    std::string lattice;
    std::string kernel_label;
    double gamma = 0;
    std::string h_model = "fixed";
    std::optional<std::string> refused; // why the lattice has no dispersion matrix; empty when it has one
    StabilityOverK over_k;
    double path_k = 0; // where the dispersion curves are drawn
    DispersionPath path;
    std::vector<StabilityOverlap> overlap;
};

struct StabilityResults : SectionResults {
    std::vector<StabilityCase> cases;

    nlohmann::json json(const Study& study) const override;
    std::string markdown(const Study& study) const override;
    void draw(const Study& study, Canvas& canvas) const override;
};

// {"gamma", "k": {"min", "max", "steps"}, "grid", "dispersion_k": a number or "best",
// "path_points", "horizon", "h_model"}.
std::shared_ptr<const StudySection> read_stability_section(const JsonNode& node,
                                                           const std::filesystem::path& study_file);

} // namespace sphkern
