#include "requests/settings/command_settings.hpp"

#include "requests/settings/shared_settings.hpp"

namespace sphkern {

SettingTable check_settings()
{
    return {"check",
            {{positional_list("kernel", "Kernel names (default with --plugin: that plugin)"),
              list("plugin", "Load this kernel plugin file too (repeatable)"), json_output(), kernel_parameters(),
              flag("all", "Check every kernel found"), flag("strict", "Exit 1 on a warning too"),
              number("timeout", "60", "Seconds a kernel may take")}}};
}

} // namespace sphkern
