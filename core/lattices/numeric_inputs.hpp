// Directions and volume coefficients given as numbers (Python), checked as the command
// line's text forms are: the same checks and messages, no text in between.
#pragma once

#include <Eigen/Core>

#include <string>
#include <vector>

namespace sphkern {

// A unit vector from `dimension` components, not all zero; `named` is the value as the
// user gave it, e.g. `--gravity "0,0,0"`, said in front of a refusal.
Eigen::Vector3d direction_of(const std::vector<double>& components, int dimension, const std::string& named);

// A volume coefficient a_p given as a number: finite, in (0, 1e6]; `text` is how it was given.
double checked_volume_coefficient(double a_p, const std::string& text);

} // namespace sphkern
