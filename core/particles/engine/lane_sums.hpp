// Eight lanes of partial sums per quantity, as two vectors of four in GCC's vector type: the
// accumulators stay in registers (an array of them was kept in memory, a load and a store per
// term; a vector of eight is split badly where registers hold four), and every lane adds in
// the same order on every instruction set, so the sums are the same bits on any machine.
#pragma once

#include "particles/engine/neighbour_gather.hpp"

#include <cstddef>

namespace sphkern {

using Quad = double __attribute__((vector_size(4 * sizeof(double))));
using UnalignedQuad = double __attribute__((vector_size(4 * sizeof(double)), aligned(alignof(double))));
static_assert(neighbour_lanes == 8);

struct Partial {
    Quad lo = {}, hi = {};
    // Quad q of the neighbours adds to lanes 0 to 3 when q is even, 4 to 7 when it is odd.
    void add(std::size_t q, const Quad& term) { (q % 2 ? hi : lo) += term; }
    double total() const { return lo[0] + lo[1] + lo[2] + lo[3] + hi[0] + hi[1] + hi[2] + hi[3]; }
};

inline const UnalignedQuad* as_quads(const double* p) { return reinterpret_cast<const UnalignedQuad*>(p); }

} // namespace sphkern
