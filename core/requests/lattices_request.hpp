// The lattices request (`sphkern lattices`, sphkern.lattices()): the shipped lattices, or
// the ones named described in full with their shells up to a radius.
#pragma once

#include "lattices/lattice.hpp"
#include "support/text/value_checks.hpp"

#include <nlohmann/json_fwd.hpp>

namespace sphkern {

// One entry per shipped lattice (name, dimension, sites, a_p, gravity, ...).
nlohmann::json lattices_listing();

// The table `sphkern lattices` prints from that list, then the example lattices shipped beside them.
void print_lattices(const nlohmann::json& listing);

// A lattice in full, each site's shells up to `radius` (a positive number in d, named by `source`).
nlohmann::json lattice_description(const Lattice& lattice, double radius, const ValueSource& source);

// The text `sphkern lattices NAME` prints, from that document.
void print_lattice_description(const Lattice& lattice, const nlohmann::json& description);

} // namespace sphkern
