// gnuplot, found on PATH and run on a script without a shell.
#pragma once

#include <filesystem>
#include <string>

namespace sphkern {

// The gnuplot executable on PATH (absolute folders only), or empty.
std::filesystem::path find_gnuplot();

// Writes `script` to folder/name.gp and runs gnuplot on it inside `folder` (an argument
// vector, a time bound); Error(output) if gnuplot fails, times out or is killed.
void run_gnuplot(const std::filesystem::path& folder, const std::string& name, const std::string& script,
                 const std::filesystem::path& gnuplot);

} // namespace sphkern
