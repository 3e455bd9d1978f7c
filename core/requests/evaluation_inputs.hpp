// The inputs eps, roots, surface and design share: the volume coefficient, gravity, the
// site and the shells summed over. Every front end gives them as numbers (the command
// line's text is parsed by its adapter); what needs the lattice is resolved once it is loaded.
#pragma once

#include "analysis/hydrostatic_errors.hpp"
#include "lattices/lattice.hpp"
#include "support/text/value_checks.hpp"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace sphkern {

// a_p as given: a name the lattice offers ("voronoi"; the command line's number text too,
// which the lattice reads after its names), or a number.
using VolumeCoefficientInput = std::variant<std::string, double>;

struct EvaluationInputs {
    VolumeCoefficientInput a_p = std::string("voronoi");
    std::optional<std::vector<double>> gravity; // none: the lattice's
    int site = 0;
    std::vector<double> shell_radii; // none: every shell inside the support
    bool continue_past_support = false;
};

// How the front end names the values in its errors.
struct EvaluationSources {
    ValueSource gravity; // "--gravity" or "gravity"
    ValueSource site;    // "--site" or "site" (a site the lattice lacks is refused as input, exit 3)
    ValueSource shells;  // e.g. "--shells 1,-1"
};

// The inputs resolved against a lattice.
struct Evaluation {
    double a_p = 0;
    Eigen::Vector3d gravity = Eigen::Vector3d::Zero();
    int site = 0;
    EvaluationMode mode;
};

// What does not need the lattice: positive shell radii.
void check_evaluation(const EvaluationInputs& inputs, const EvaluationSources& sources);

// The volume coefficient a_p: a name the lattice offers or a positive number up to 1e6.
double volume_coefficient_of(const Lattice& lattice, const VolumeCoefficientInput& a_p);

// a_p, then the site, then gravity (as many components as the lattice has dimensions).
Evaluation resolve_evaluation(const EvaluationInputs& inputs, const EvaluationSources& sources, const Lattice& lattice);

} // namespace sphkern
