#include "codes/neighbour_number.hpp"

#include <cmath>
#include <numbers>

namespace sphkern {

double neighbour_number(int dim, double support, double spacing)
{
    const double ball = dim == 3 ? 4 * std::numbers::pi / 3 : dim == 2 ? std::numbers::pi : 2;
    return ball * std::pow(support, dim) / std::pow(spacing, dim);
}

} // namespace sphkern
