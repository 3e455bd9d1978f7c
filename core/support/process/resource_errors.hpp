// A system resource that ran out (open files, processes) is named as what it is, so that an
// error never blames a plugin, a kernel or a name for a limit of the machine or the shell.
#pragma once

#include "support/error.hpp"

#include <string>

namespace sphkern {

// An input error (exit 3) that no caller may take for a fault of the file or plugin at hand:
// a loop that skips broken files stops on it.
class ResourceError : public Error {
public:
    explicit ResourceError(const std::string& message) : Error(ExitCode::input, message) {}
};

// errno values that mean a per-process or system limit.
bool is_resource_error(int error);

// Throws ResourceError: `doing` failed because of the limit behind `error`, and how to raise it.
[[noreturn]] void fail_resource(int error, const std::string& doing);

} // namespace sphkern
