#include "requests/settings/command_settings.hpp"

#include "requests/settings/shared_settings.hpp"

namespace sphkern {

SettingTable kernels_settings() { return {"kernels", {{plugin_files(), json_output()}}}; }

} // namespace sphkern
