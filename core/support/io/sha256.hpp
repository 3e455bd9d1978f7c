// SHA-256 (FIPS 180-4) of bytes and of files, as lowercase hex: what a results file
// records of each input so that the input can be recognised later.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace sphkern {

std::string sha256_hex(std::string_view bytes);

// The whole file, read in chunks; throws Error(input) if it cannot be read.
std::string file_sha256_hex(const std::filesystem::path& file);

} // namespace sphkern
