#include "particles/particles_memory.hpp"

#include "support/error.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <string>

namespace sphkern {

namespace {

std::size_t limit = 0;

std::size_t available_memory()
{
    std::ifstream meminfo("/proc/meminfo");
    std::string key;
    std::size_t kib = 0;
    std::string unit;
    while (meminfo >> key >> kib >> unit)
        if (key == "MemAvailable:") return kib * 1024;
    return std::size_t{4} << 30; // no /proc: a modest machine
}

} // namespace

void set_memory_limit_gib(double gib)
{
    limit = static_cast<std::size_t>(gib * static_cast<double>(std::size_t{1} << 30));
}

std::size_t memory_limit_bytes() { return limit ? limit : available_memory() / 4 * 3; }
std::size_t max_particles() { return memory_limit_bytes() / bytes_per_particle; }
std::size_t particle_file_byte_limit() { return memory_limit_bytes() / 3; }

} // namespace sphkern
