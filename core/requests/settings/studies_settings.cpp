#include "requests/settings/command_settings.hpp"

#include "requests/settings/shared_settings.hpp"

namespace sphkern {

SettingTable studies_settings() { return {"studies", {{json_output()}}}; }

} // namespace sphkern
