// What the parts of a study's report write alike.
#pragma once

#include "analysis/acceptance.hpp"

#include <string>
#include <vector>

namespace sphkern {

// The method document: a copy travels with every results folder (method_document_path()),
// so the link is relative and holds wherever the folder is moved or sent.
inline std::string method_document() { return "[method.md](method.md)"; }

// "[a, b] [c, d]", or `none` if there is no interval.
std::string intervals_text(const std::vector<KInterval>& intervals, const std::string& none);
// A condition (22) verdict's intervals, or "-".
std::string intervals_text(const Acceptance& a);

} // namespace sphkern
