#include "particles/engine/periodic_images.hpp"

#include <Eigen/LU>

namespace sphkern {

PeriodicImages::PeriodicImages(const PeriodicBox& box, int dimension, double reach) : dim_(dimension), cell_(box.edges)
{
    if (dim_ == 2) cell_.col(2) = Eigen::Vector3d::UnitZ();
    inverse_ = cell_.inverse();
    // An image is needed where it lies within `reach` of the box: within this fractional
    // margin of a face along each edge.
    for (int a = 0; a < dim_; ++a) margin_[a] = reach * inverse_.row(a).norm() * (1 + 1e-9);
}

} // namespace sphkern
