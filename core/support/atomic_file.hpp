// Writes a file completely or not at all: into a temporary sibling, then renamed.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>

namespace sphkern {

// Throws Error(output) if the file cannot be written.
void write_file_atomically(const std::filesystem::path& file, const std::function<void(std::ostream&)>& write);

} // namespace sphkern
