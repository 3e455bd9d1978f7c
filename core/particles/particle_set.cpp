#include "particles/particle_set.hpp"

#include "support/error.hpp"
#include "support/process/parallel_for.hpp"

#include <Eigen/LU>
#include <fmt/format.h>

#include <cmath>
#include <optional>

namespace sphkern {

double PeriodicBox::volume(int dimension) const
{
    return dimension == 2 ? std::abs(edges(0, 0) * edges(1, 1) - edges(0, 1) * edges(1, 0))
                          : std::abs(edges.determinant());
}

double PeriodicBox::smallest_width(int dimension) const
{
    // Width along edge a = volume / area of the opposite face = 1 / |row a of the inverse|.
    Eigen::Matrix3d cell = edges;
    if (dimension == 2) cell.col(2) = Eigen::Vector3d::UnitZ();
    const Eigen::Matrix3d inverse = cell.inverse();
    double width = INFINITY;
    for (int a = 0; a < dimension; ++a) width = std::min(width, 1 / inverse.row(a).norm());
    return width;
}

std::string ParticleSet::particle(std::size_t i) const
{
    for (auto a = arrays.rbegin(); arrays.size() > 1 && a != arrays.rend(); ++a)
        if (i >= a->second) return fmt::format("particle {} of array \"{}\"", i - a->second, a->first);
    return fmt::format("particle {}", id(i));
}

namespace {

void check_positive(const ParticleValues& values, const ParticleSet& set, const char* field, int threads)
{
    if (values.empty()) return;
    if (values.size() != set.size())
        fail_input(fmt::format("{}: {} has {} values for {} particles", set.name, field, values.size(), set.size()));
    if (const auto i = first_index_where(values.size(), threads,
                                         [&](std::size_t i) { return !std::isfinite(values[i]) || values[i] <= 0; }))
        fail_input(fmt::format("{}: {} of {} is {}, expected a positive finite number", set.name, field,
                               set.particle(*i), values[*i]));
}

} // namespace

double mean_volume(const ParticleSet& set) { return set.box->volume(set.dimension) / static_cast<double>(set.size()); }

double mean_spacing(const ParticleSet& set) { return std::pow(mean_volume(set), 1.0 / set.dimension); }

void wrap_into_box(ParticleSet& set, WrapReach reach, int threads)
{
    Eigen::Matrix3d cell = set.box->edges;
    if (set.dimension == 2) cell.col(2) = Eigen::Vector3d::UnitZ();
    const Eigen::Matrix3d inverse = cell.inverse();
    // Wraps particle i; false for one more than one box outside (not a rounding matter: the box is wrong).
    auto wrap = [&](std::size_t i) {
        Eigen::Vector3d f = inverse * set.position(i);
        bool moved = false;
        for (int a = 0; a < set.dimension; ++a) {
            if (reach == WrapReach::one_box && (f[a] < -1 || f[a] >= 2)) return false;
            if (f[a] < 0 || f[a] >= 1) f[a] -= std::floor(f[a]), moved = true;
        }
        if (!moved) return true;
        const Eigen::Vector3d p = cell * f;
        set.x[i] = p.x(), set.y[i] = p.y(), set.z[i] = set.dimension == 2 ? 0.0 : p.z();
        return true;
    };
    if (const auto i = first_index_where(set.size(), threads, [&](std::size_t i) { return !wrap(i); }))
        fail_input(fmt::format("{}: {} at ({:g}, {:g}, {:g}) lies outside the periodic box", set.name, set.particle(*i),
                               set.x[*i], set.y[*i], set.z[*i]));
}

void validate_particle_set(ParticleSet& set, int threads)
{
    if (set.dimension != 2 && set.dimension != 3)
        fail_input(fmt::format("{}: particles in {} dimensions; expected 2 or 3", set.name, set.dimension));
    if (set.size() < 2) fail_input(fmt::format("{}: {} particles; expected at least 2", set.name, set.size()));
    if (set.y.size() != set.size() || set.z.size() != set.size())
        fail_input(fmt::format("{}: the coordinate arrays differ in length", set.name));
    if (set.box) {
        const double volume = set.box->volume(set.dimension);
        if (!std::isfinite(volume) || volume <= 0)
            fail_input(fmt::format("{}: the periodic box has no volume; expected {} independent edges", set.name,
                                   set.dimension));
    }
    validate_particle_values(set, threads);
}

void validate_particle_values(ParticleSet& set, int threads)
{
    const auto not_finite = [&](std::size_t i) {
        return !std::isfinite(set.x[i]) || !std::isfinite(set.y[i]) || !std::isfinite(set.z[i]);
    };
    if (const auto i = first_index_where(set.size(), threads, not_finite))
        fail_input(fmt::format("{}: {} has a non-finite coordinate ({}, {}, {})", set.name, set.particle(*i), set.x[*i],
                               set.y[*i], set.z[*i]));
    check_positive(set.h, set, "the smoothing length", threads);
    check_positive(set.mass, set, "the mass", threads);
    check_positive(set.density, set, "the density", threads);
    if (set.box) wrap_into_box(set, WrapReach::one_box, threads);
}

} // namespace sphkern
