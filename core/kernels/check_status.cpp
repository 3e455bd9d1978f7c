#include "kernels/check_status.hpp"

#include "support/error.hpp"

#include <string>

namespace sphkern {

namespace {

constexpr const char* names[] = {"ok", "warn", "fail"}; // in the enum's order

} // namespace

const char* check_status_name(CheckStatus status) { return names[static_cast<int>(status)]; }

CheckStatus check_status_named(std::string_view name)
{
    for (int s = 0; s < 3; ++s)
        if (name == names[s]) return static_cast<CheckStatus>(s);
    throw Error(ExitCode::plugin, "kernel check: unknown verdict \"" + std::string(name) + "\"");
}

} // namespace sphkern
