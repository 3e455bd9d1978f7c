// A system resource that ran out (open files, processes) is named as what it is, so that an
// error never blames a plugin, a kernel or a name for a limit of the machine or the shell.
#pragma once

#include <string>

namespace sphkern {

// errno values that mean a per-process or system limit.
bool is_resource_error(int error);

// Throws Error(input): `doing` failed because of the limit behind `error`, and how to raise it.
[[noreturn]] void fail_resource(int error, const std::string& doing);

} // namespace sphkern
