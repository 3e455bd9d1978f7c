// A quantity of every particle: an array, or one value for all (h from N_H or eta, the
// volumes of a uniform set). A set of 10^8 particles then keeps no 800 MB array holding one
// number, and the engine, told the value is uniform, gathers nothing into its point order.
#pragma once

#include "support/process/first_touch.hpp"

#include <cstddef>
#include <span>

namespace sphkern {

// A view of one, as the engine reads it.
struct PerParticleView {
    std::span<const double> values; // empty: every particle has `uniform`
    double uniform = 0;
    std::size_t count = 0;

    static PerParticleView of(std::span<const double> values) { return {values, 0.0, values.size()}; }
    bool is_uniform() const { return values.empty(); }
    std::size_t size() const { return count; }
    double operator[](std::size_t i) const { return values.empty() ? uniform : values[i]; }
};

struct PerParticle {
    ParticleValues values; // empty: every particle has `uniform`
    double uniform = 0;
    std::size_t count = 0;

    static PerParticle same(std::size_t n, double value) { return {{}, value, n}; }
    static PerParticle of(ParticleValues values)
    {
        const std::size_t n = values.size();
        return {std::move(values), 0.0, n};
    }
    bool is_uniform() const { return values.empty(); }
    std::size_t size() const { return count; }
    double operator[](std::size_t i) const { return values.empty() ? uniform : values[i]; }
    PerParticleView view() const { return {values, uniform, count}; }
};

} // namespace sphkern
