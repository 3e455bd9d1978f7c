// One shells request (`sphkern shells`, sphkern.shells): the neighbour shells of a lattice
// site up to a radius, with each shell's moment along a direction; each value checked once
// and named as the front end names it.
#pragma once

#include "lattices/lattice.hpp"
#include "support/text/value_checks.hpp"

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <vector>

namespace sphkern {

struct ShellsRequest {
    double radius = 0; // in units of d
    int site = 0;
    std::optional<std::vector<double>> gravity; // none: the lattice's
};

struct ShellsSources {
    ValueSource radius, site, gravity;
};
ShellsSources shells_sources(FrontEnd front_end);

// A positive radius, a site the lattice has, a direction of its dimension: the document
// `sphkern shells --json` prints (without provenance and inputs).
nlohmann::json run_shells(const ShellsRequest& request, const ShellsSources& sources, const Lattice& lattice);

// The text `sphkern shells` prints, from that document.
void print_shells(const nlohmann::json& document);

} // namespace sphkern
