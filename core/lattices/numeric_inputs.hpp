// Directions and volume coefficients given as numbers (Python), checked as the command
// line's text forms are: the same checks and messages, no text in between.
#pragma once

#include "support/text/value_checks.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace sphkern {

// A direction of `dimension` components (a set's or lattice's dimension; another count is an
// input that does not fit, exit 3), finite and not all zero (else the source's code): the unit vector.
Eigen::Vector3d direction_of(const std::vector<double>& components, int dimension, const ValueSource& source);

// A volume coefficient a_p given as a number: finite, in (0, 1e6]; `text` is how it was given.
double checked_volume_coefficient(double a_p, const std::string& text);

} // namespace sphkern
