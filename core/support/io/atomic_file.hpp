// Writes a file completely or not at all: into a temporary sibling, then renamed.
// Only a regular file is ever replaced: a device, a link, a pipe or a folder in the
// way is refused, so that sphkern cannot damage what it did not write.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>

namespace sphkern {

// Throws Error(output) if the file cannot be written or something other than a
// regular file is in its place.
void write_file_atomically(const std::filesystem::path& file, const std::function<void(std::ostream&)>& write);

} // namespace sphkern
