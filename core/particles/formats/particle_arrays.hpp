// The PySPH particle arrays a run reads (`--array fluid,solid`): the measures on the first
// array's particles, the others' particles their neighbours only (walls, solids).
#pragma once

#include <string>
#include <vector>

namespace sphkern {

// The names of a comma-separated list, in order; empty for an empty list.
std::vector<std::string> particle_array_names(const std::string& list);

// Why a list cannot name arrays (an empty name, a name given twice), "" where it can.
std::string particle_array_list_problem(const std::string& list);

} // namespace sphkern
