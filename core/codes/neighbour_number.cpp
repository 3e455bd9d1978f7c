#include "codes/neighbour_number.hpp"

#include <cmath>
#include <numbers>

namespace sphkern {

double neighbour_number(int dim, double support, double spacing)
{
    const double ball = dim == 3 ? 4 * std::numbers::pi / 3 : dim == 2 ? std::numbers::pi : 2;
    return ball * std::pow(support, dim) / std::pow(spacing, dim);
}

void set_neighbour_number(CodeProfile& p)
{
    p.counts_neighbours = true;
    p.layout = CodeLayout::gadget;
    p.hdf5_suffix = ".hdf5";
    p.hdf5_suffix_reason = "GADGET opens <InitCondFile>.hdf5 for HDF5 initial conditions (ICFormat 3)";
    p.support_per_h = [](const Kernel&, int) { return 1.0; };
    p.parameter_of = [](const Kernel& kernel, int dim, double k, double spacing) {
        return neighbour_number(dim, kernel.support() * k, spacing);
    };
}

} // namespace sphkern
