// SHA-256 (FIPS 180-4) of files, as lowercase hex: what a results file
// records of each input so that the input can be recognised later.
#pragma once

#include <filesystem>
#include <string>

namespace sphkern {

// The whole file, read in chunks; throws Error(input) if it cannot be read.
std::string file_sha256_hex(const std::filesystem::path& file);

} // namespace sphkern
