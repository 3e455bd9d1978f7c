// Text that came from a data file or a plugin, made safe to print: valid UTF-8 (a byte that
// starts no valid sequence becomes U+FFFD), and no control character that a terminal would
// act on (C0, DEL and C1 are shown as \xNN). Applied where such text enters sphkern.
#pragma once

#include <string>
#include <string_view>

namespace sphkern {

std::string printable_text(std::string_view text);

} // namespace sphkern
