#include "kernels/plugin_host/plugin_host.hpp"

#include "kernels/plugin_host/plugin_faults.hpp"
#include "kernels/plugin_host/plugin_watchdog.hpp"
#include "support/process/interruption.hpp"

#include <mutex>

namespace sphkern {

static_assert(fault_signal_count <= max_hooked_signals);

void host_plugins()
{
    static std::once_flag once;
    std::call_once(once, [] {
        set_signal_hook({take_fault_signals, give_back_fault_signals});
        start_plugin_watchdog();
    });
}

} // namespace sphkern
