// A study: kernels x lattices x volume coefficients x evaluation modes over a
// k-interval, read from a JSON file (the format: share/docs/study-format.md and
// share/schemas/study.schema.json).
#pragma once

#include "analysis/hydrostatic_errors.hpp"
#include "analysis/resolution_axis.hpp"
#include "analysis/surface_profile.hpp"
#include "stability/h_model.hpp"
#include "study/reference_table.hpp"
#include "study/study_particles.hpp"
#include "support/text/value_checks.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
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

// The optional free-surface section: a profile per lattice, kernel and form.
struct StudySurface {
    std::optional<double> k;           // empty: each kernel's best k (condition 22, first mode)
    int layers = 6;
    std::vector<GradientForm> forms = {GradientForm::sum};
    std::optional<StudyVolumeCoefficient> volume_coefficient; // empty: the study's first
};

// An optional parameter sweep: maps of both errors over (k, parameter) and the
// (k, parameter) where both vanish.
struct StudySweep {
    std::string kernel; // name, plugin or expression file, or a blend A+B
    std::map<std::string, double> parameters; // other parameter values
    std::string parameter;
    double min = 0, max = 1;
    int samples = 41;
    std::string json_path;
};

// The optional stability section: min omega^2 against k, the stable k intervals and the
// dispersion curves of every kernel on every lattice.
struct StudyStability {
    double gamma = 5.0 / 3.0;
    std::optional<double> k_min, k_max; // empty: the study's window in k, over its volume coefficients
    int steps = 100;                    // k samples - 1
    int grid = 0;                       // first zone grid per reciprocal axis; 0: 8 in 3D, 32 in 2D
    std::optional<double> path_k;       // the dispersion curves' k; empty: the best k of condition (22)
    int path_points = 120;
    double horizon = 100;               // growth time in d/c: slower instabilities are weak (default_horizon)
    HModel h_model = HModel::fixed;     // fixed or adaptive h
};

// A study's total work, bounded before it starts (see check in parse_study).
inline constexpr double max_study_curve_points = 2e6;
inline constexpr double max_study_sweep_points = 2e6;
inline constexpr double max_study_surface_layers = 1e6;
inline constexpr double max_study_stability_points = 1e8; // wave vectors over all k samples (as max_stability_points)
inline constexpr double max_study_particle_evaluations = 1e8; // particles x N_H values, over all sources

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
    std::optional<StudySurface> surface;
    std::vector<StudySweep> sweeps;
    std::optional<StudyStability> stability;
    std::optional<StudyParticles> particles;
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

} // namespace sphkern
