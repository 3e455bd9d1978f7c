// Where a result comes from: the program and its build, the machine, the time and the
// command line. Every results.json and every --json document carries it under
// "provenance"; the study layer adds the inputs in full (study/study_provenance.hpp).
#pragma once

#include <nlohmann/json_fwd.hpp>

namespace sphkern {

// Called once by main: the command line as typed, recorded by provenance().
void record_command_line(int argc, const char* const* argv);

// {"sphkern_version", "git_describe", "build_type", "compiler", "date_utc",
//  "command_line", "host": {"cpu", "threads"}}; what is not known is "unknown".
nlohmann::json provenance();

// "sphkern 0.1.0 (git ..., Release, GNU 12.2.0)": what --version prints.
std::string version_text();

} // namespace sphkern
