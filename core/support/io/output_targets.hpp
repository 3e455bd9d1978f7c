// The files a command is asked to write, checked together before any work: none of them is a
// file this run reads, no two of them are one file, and each is absent or a regular file the
// user may write, as the shell would judge it. Every writer of a command line goes through it.
#pragma once

#include <string>
#include <vector>

namespace sphkern {

struct OutputTarget {
    std::string option; // as the front end names it
    std::string path;   // as given; empty is refused
};

// Throws Error(usage) for an empty name and Error(output) for the rest, naming the option.
void check_output_targets(const std::vector<OutputTarget>& outputs, const std::vector<std::string>& inputs);

} // namespace sphkern
