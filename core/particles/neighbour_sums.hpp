// The sums of the particle measures over one particle's gathered neighbours: V_j W, m_j W,
// the first moment, the gradient of a constant and the linear-gradient tensor, each in eight
// lanes of partial sums added in a fixed order at the end, so that the loops vectorise and the
// result is the same bits on any machine and thread count.
#pragma once

#include "particles/engine/neighbour_gather.hpp"

#include <cstddef>

namespace sphkern {

enum NeighbourSum { s0, sm, m1x, m1y, m1z, e1x, e1y, e1z, exx, eyy, ezz, exy, exz, eyz, neighbour_sum_count };

// total[s] over the first `padded` entries of nb (nb.count neighbours, then padding that adds
// zero) with W and W' in nb.w and nb.dw, 1 / r in nb.inv_r: V_j = uniform_volume for every j
// when it is positive (then W and W' of the padding are set to 0), nb.a otherwise; m_j in nb.b
// when with_mass (total[sm] = 0 otherwise). The terms with z only when with_z.
void neighbour_sums(Neighbours& nb, std::size_t padded, double uniform_volume, bool with_mass, bool with_z,
                    double* total);

} // namespace sphkern
