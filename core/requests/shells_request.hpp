// One shells request (`sphkern shells`, sphkern.shells): the neighbour shells of a lattice
// site up to a radius, with each shell's moment along a direction; each value checked once
// and named as the front end names it.
#pragma once

#include "lattices/lattice.hpp"
#include "lattices/shells.hpp"
#include "support/text/value_checks.hpp"

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <string>
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

// The shells of a site up to a radius, each with its moment along the request's direction.
struct ShellsResult {
    std::string lattice;
    int site = 0;
    double radius = 0;
    std::vector<ShellRow> shells;
};

// A positive radius, a site the lattice has, a direction of its dimension; an Error naming
// the value's source otherwise.
ShellsResult run_shells(const ShellsRequest& request, const ShellsSources& sources, const Lattice& lattice);

// The document `sphkern shells --json` prints (without provenance and inputs) and Python returns.
nlohmann::json shells_json(const ShellsResult& result);
// The text `sphkern shells` prints.
void print_shells(const ShellsResult& result);

} // namespace sphkern
