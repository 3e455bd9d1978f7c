// A study: kernels x lattices x volume coefficients x evaluation modes over a
// k-interval, read from a JSON file (the format: share/docs/study-format.md and
// share/schemas/study.schema.json).
#pragma once

#include "analysis/hydrostatic_errors.hpp"
#include "analysis/resolution_axis.hpp"
#include "study/reference_table.hpp"
#include "study/sections/study_section.hpp"
#include "support/text/value_checks.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace sphkern {

struct StudyKernel {
    std::string spec; // name or plugin file
    std::map<std::string, double> parameters;
    std::string json_path;
};

struct StudyMode {
    std::string name;
    // Explicit shell radii per kernel support R (keys "1", "2", ... read as numbers); empty: automatic shells.
    std::map<double, std::vector<double>> shells_by_support;
    bool continue_all = false;
    std::vector<std::string> continue_kernels; // kernels whose formula is continued past R
    std::string json_path;

    bool is_automatic() const { return shells_by_support.empty() && !continue_all && continue_kernels.empty(); }
    bool continues(const std::string& kernel) const;
    // The shell list for a kernel of support R, or nullptr.
    const std::vector<double>* shells_for(double R) const;
};

// A volume coefficient a_p: one of each lattice's named coefficients, or a number.
struct StudyVolumeCoefficient {
    std::string name;            // as the study gives it: "voronoi", or the number as written
    std::optional<double> value; // the number, when one is given (as a number or as text)

    // The number, or the lattice's coefficient of that name (Error(input) if it has none).
    double on(const Lattice& lattice) const;
};

// The bulk cases' work, bounded before anything starts (each section bounds its own).
inline constexpr double max_study_curve_points = 2e6;

// Where a study's document was read, for its errors: the study file, or a results file
// and the pointer of its "study" entry when `run --reproduce` reads the study back.
struct StudyOrigin {
    std::string file;
    std::string pointer; // "" for a study file, "/study" in a results file
};

struct Study {
    std::string file;
    StudyOrigin origin;
    nlohmann::json document; // echoed into results.json
    std::string name;
    std::string title;
    std::vector<StudyKernel> kernels;
    std::vector<std::string> lattices;
    std::vector<StudyVolumeCoefficient> volume_coefficients;
    double k_min = 0.75, k_max = 1.25; // the window, on `axis`
    Axis axis = Axis::k;
    int samples = 501;
    double epsilon = 0.01;
    std::optional<std::vector<int>> sites; // "sites": indices into every lattice's motif; absent or "all": every site
    bool lateral = false;                  // the lateral gradient error counts in condition (22)
    std::vector<StudyMode> modes;
    std::optional<ReferenceTable> reference; // "compare_with": a reference table (share/reference), read and checked
    bool plots = true;
    std::vector<std::shared_ptr<const StudySection>> sections; // [section_table()]: null where the study has none
};

Study read_study(const std::filesystem::path& file);

// Validates a parsed study document; `file` anchors relative paths and names it in errors,
// unless `origin` says where else the document was read.
Study parse_study(nlohmann::json document, const std::filesystem::path& file, std::optional<StudyOrigin> origin = {});

// The place of `pointer` in the study's document, as its errors name it ("s.json: /k" or
// "results.json: /study/k"), with exit code 3.
ValueSource study_source(const Study& study, const std::string& pointer);

// Parses a shell radius: a number or "sqrt(N)".
std::optional<double> parse_radius(const nlohmann::json& value);

// The readers the spine and the sections share.
inline const std::vector<std::string> kernel_file_extensions = {".so", ".json"};
std::vector<std::string> read_string_list(const JsonNode& node);
std::map<std::string, double> read_parameter_values(const JsonNode& set); // "set": {"parameter": value, ...}
StudyVolumeCoefficient read_volume_coefficient(const JsonNode& item);     // a name, or a number (as number or text)
std::optional<double> read_k_or_best(const JsonNode& node);               // a number, or "best" (empty)

} // namespace sphkern
