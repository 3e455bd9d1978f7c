// The studies request (`sphkern studies`): the shipped studies, each with its title and what it runs.
#pragma once

#include <nlohmann/json_fwd.hpp>

namespace sphkern {

// One entry per shipped study: name, title, number of kernels, lattices, file.
nlohmann::json studies_listing();

// The text `sphkern studies` prints, from that list.
void print_studies(const nlohmann::json& listing);

} // namespace sphkern
