// Results are written to a private copy of the original standard output; descriptor 1
// itself is pointed at stderr, so that whatever a plugin prints (printf, puts) lands
// among the logs and never inside sphkern's tables or JSON.
#pragma once

#include <cstdio>

namespace sphkern {

// Copies stdout to a new descriptor for results and points descriptor 1 at stderr.
void separate_results_from_stdout();

// Where results go: the copy, or plain stdout before separate_results_from_stdout.
std::FILE* results_file();

// Throws Error(plugin) if the results descriptor no longer refers to the file it did
// at the start (a plugin closed or replaced it), and points descriptor 1 at stderr again.
void check_results_output();

} // namespace sphkern
