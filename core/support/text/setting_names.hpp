// How the running front end spells a setting in the hints that the layers below requests/
// give ("a smaller --dt" on the command line, "a smaller dt" in Python), from its key in
// Python's spelling. The front end says which it is once, before any work; the command
// line is the default.
#pragma once

#include "support/text/value_checks.hpp"

#include <string>
#include <string_view>

namespace sphkern {

void name_settings_for(FrontEnd front_end);

std::string setting_named(std::string_view key);

} // namespace sphkern
