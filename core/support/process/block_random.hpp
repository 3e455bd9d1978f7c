// Random numbers drawn block by block of particles, each block from a stream of its own seeded
// by (seed, block): a set is the same whatever the thread count that draws it, and its blocks
// are drawn in parallel.
#pragma once

#include <boost/random/mersenne_twister.hpp>

#include <cstddef>
#include <cstdint>
#include <random>

namespace sphkern {

// The particles drawn from one stream: the sets a seed gives depend on it, so it is fixed
// apart from the blocks of the parallel passes.
inline constexpr std::size_t random_block_size = std::size_t{1} << 16;

// The stream of block `block` of a set drawn with `seed` (std::seed_seq's mixing is fixed by
// the standard, Boost's generator by its own: the same numbers on every platform).
inline boost::random::mt19937_64 block_stream(std::uint64_t seed, std::uint64_t block)
{
    std::seed_seq sequence{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                           static_cast<std::uint32_t>(block), static_cast<std::uint32_t>(block >> 32)};
    return boost::random::mt19937_64(sequence);
}

} // namespace sphkern
