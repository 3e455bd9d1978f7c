// The periodic images of a particle that lie within a reach of its box: the ghosts a
// neighbour search adds at the faces. One formula for the grid and for the slabs of a set
// read in parts, so that both find the same images at the same coordinates, bit for bit.
#pragma once

#include "particles/particle_set.hpp"

#include <Eigen/Core>

#include <optional>

namespace sphkern {

class PeriodicImages {
public:
    PeriodicImages(const PeriodicBox& box, int dimension, double reach);

    // visit(x, y, z) for each image of `position` (inside the box) near the box, in a fixed order.
    template <class Visit>
    void of(const Eigen::Vector3d& position, const Visit& visit) const
    {
        const Eigen::Vector3d f = inverse_ * position;
        // Most particles lie farther than the margin from every face: no image of theirs is near.
        bool inner = true;
        for (int d = 0; d < dim_; ++d) inner = inner && f[d] >= margin_[d] && f[d] < 1 - margin_[d];
        if (inner) return;
        const int nz = dim_ == 3 ? 1 : 0;
        for (int a = -1; a <= 1; ++a)
            for (int b = -1; b <= 1; ++b)
                for (int c = -nz; c <= nz; ++c) {
                    if (a == 0 && b == 0 && c == 0) continue;
                    const Eigen::Vector3d image = f + Eigen::Vector3d(a, b, c);
                    bool near = true;
                    for (int d = 0; d < dim_; ++d) near = near && image[d] >= -margin_[d] && image[d] < 1 + margin_[d];
                    if (!near) continue;
                    const Eigen::Vector3d p = cell_ * image;
                    visit(p.x(), p.y(), dim_ == 3 ? p.z() : 0.0);
                }
    }

private:
    int dim_;
    Eigen::Matrix3d cell_, inverse_;
    Eigen::Vector3d margin_ = Eigen::Vector3d::Zero();
};

// The images of a set's particles (none without a box).
inline std::optional<PeriodicImages> periodic_images_of(const ParticleSet& set, double reach)
{
    if (!set.box) return std::nullopt;
    return PeriodicImages(*set.box, set.dimension, reach);
}

// visit(x, y, z) for particle i's own point, then each of its images near the box.
template <class Visit>
void for_each_point(const ParticleSet& set, std::size_t i, const std::optional<PeriodicImages>& images,
                    const Visit& visit)
{
    visit(set.x[i], set.y[i], set.z[i]);
    if (images) images->of(set.position(i), visit);
}

} // namespace sphkern
