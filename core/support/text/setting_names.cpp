#include "support/text/setting_names.hpp"

#include <atomic>

namespace sphkern {

namespace {
std::atomic<FrontEnd> running_front_end{FrontEnd::command_line};
}

void name_settings_for(FrontEnd front_end) { running_front_end = front_end; }

std::string setting_named(std::string_view key) { return value_named(running_front_end, key).name; }

} // namespace sphkern
