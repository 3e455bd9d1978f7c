// A setting named in a message by a layer below requests/, which knows no front end ("a
// smaller dt"): a mark of its key (Python's spelling) that the front end showing the message
// spells its own way, "--dt" on the command line, "dt" in Python (spell_settings). No front
// end is remembered here: each spells the messages it shows.
#pragma once

#include <functional>
#include <string>
#include <string_view>

namespace sphkern {

// "{{max_move}}": the mark of a setting in a message.
std::string setting_named(std::string_view key);

// The message with each mark replaced by spell(key).
std::string spell_settings(std::string_view message, const std::function<std::string(std::string_view)>& spell);

} // namespace sphkern
