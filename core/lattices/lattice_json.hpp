// A lattice's description as JSON: what `lattices --json` and `shells --json` print and the
// Python module returns.
#pragma once

#include "lattices/lattice.hpp"

#include <Eigen/Core>
#include <nlohmann/json_fwd.hpp>

namespace sphkern {

nlohmann::json lattice_json(const Lattice& lattice);
// A lattice in full, as `lattices NAME|FILE --json` prints it: lattice_json plus every
// site (fractional and Cartesian, in d) with its shells up to `radius`.
nlohmann::json lattice_description_json(const Lattice& lattice, double radius);
nlohmann::json shells_json(const Lattice& lattice, int site, double radius, const Eigen::Vector3d& gravity);

} // namespace sphkern
