// The "particles" section: every kernel of the study on particle sets that are no lattice
// (disturbed lattice blocks, Poisson sets, files, any of them relaxed first), over a range
// of N_H or eta; a report table and a figure per source (RMS e0 and eps_gradp against N_H,
// log-log, a curve per kernel, the Poisson limit for reference).
#pragma once

#include "particles/particle_analysis.hpp"
#include "particles/sources/particle_source.hpp"
#include "relax/relax_settings.hpp"
#include "study/sections/study_section.hpp"
#include "support/io/json_input.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sphkern {

// A source relaxed into a glass before it is measured: by one of the study's kernels at one
// N_H (or eta), for a number of steps.
struct StudyRelax {
    std::string kernel;
    SmoothingSpec smoothing{SmoothingRule::nh, 100, 0};
    RelaxSettings settings;
    std::string json_path;
};

struct StudyParticleSource {
    std::string label; // "fcc, sigma = 0.1 d, 20x20x20", "poisson, 3D, 20000", the file
    std::string json_path;
    ParticleSource source;
    std::optional<StudyRelax> relax;
};

// A code's setting in place of the sweep: its parameter's value (h as the code sets it), or
// none (a file's stored h as the code stores it).
struct StudyCode {
    std::string name;
    std::optional<double> value;
    std::string json_path; // of "code"
};

struct StudyParticles {
    std::vector<StudyParticleSource> sources;
    SmoothingSweep sweep{SmoothingRule::nh, 20, 200, 9};
    std::optional<StudyCode> code; // instead of the sweep
    std::optional<VolumeModel> volume;
    std::string json_path;
};

struct ParticlesCase {
    std::string source, kernel_label;
    int dimension = 0;
    std::size_t particles = 0;
    VolumeModel volume = VolumeModel::uniform;
    std::vector<ParticlePoint> points;
    std::vector<double> poisson_rms_e0; // per point: a Poisson set of as many particles at that h
    std::string code; // the code's setting the one point is at ("swift eta = 1.2348: ..."); empty: a sweep
};

struct ParticlesResults : SectionResults {
    std::vector<ParticlesCase> cases;

    nlohmann::json json(const Study& study) const override;
    std::string markdown(const Study& study) const override;
    void draw(const Study& study, Canvas& canvas) const override;
};

// Reads the section: {"sources": [...], "nh" or "eta": {"min", "max", "steps"}, or "code":
// {"name", and the code's parameter by its name ("eta", "hfact", "nngb", "hdx", "coefh")}, "volume"};
// each source one of {"lattice", "size", "sigma", "seed"}, {"poisson": D, "count", "seed",
// "box"} or {"file", "box", "array", "dim"}, relative files beside the study; any of them with
// "relax": {"kernel", "nh" or "eta", "steps", "method"}.
StudyParticles read_study_particles(const JsonNode& node, const std::filesystem::path& study_file);

// An upper bound of the particles the section evaluates, over all sources and h (the budget).
double study_particle_evaluations(const StudyParticles& particles);

// The section, read (read_study_particles) for the table of sections.
std::shared_ptr<const StudySection> read_particles_section(const JsonNode& node,
                                                           const std::filesystem::path& study_file);

} // namespace sphkern
