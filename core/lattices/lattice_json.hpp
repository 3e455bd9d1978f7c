// A lattice's description as JSON: what `lattices --json` and `shells --json` print and the
// Python module returns.
#pragma once

#include "lattices/lattice.hpp"
#include "lattices/shells.hpp"

#include <Eigen/Core>
#include <nlohmann/json_fwd.hpp>

#include <vector>

namespace sphkern {

nlohmann::json lattice_json(const Lattice& lattice);
// A lattice in full, as `lattices NAME|FILE --json` prints it: lattice_json plus every
// site (fractional and Cartesian, in d) with its shells up to `radius`.
nlohmann::json lattice_description_json(const Lattice& lattice, double radius);
// The rows of shell_rows as the JSON of `shells` and `lattices NAME` lists them.
nlohmann::json shell_rows_json(const std::vector<ShellRow>& rows);

} // namespace sphkern
