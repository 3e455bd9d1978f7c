#include "kernels/plugin_host/plugin_watchdog.hpp"

#include "kernels/plugin_host/plugin_call_guard.hpp"
#include "kernels/plugin_host/plugin_faults.hpp"
#include "support/error.hpp"
#include "support/process/interruption.hpp"

#include <spdlog/spdlog.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <thread>

namespace sphkern {

namespace {

constexpr auto tick = std::chrono::milliseconds(100);
constexpr int interrupt_ticks = 8;  // a signal is obeyed within 0.8 s and a tick
constexpr int long_call_ticks = 10; // a call this long is logged (tests wait for the line)

// How long each watched thread has been inside one and the same call.
struct Watch {
    std::uint64_t sequence = 0;
    int ticks = 0;
};

[[noreturn]] void end_for_hang(const PluginCall& call, double seconds)
{
    char what[96];
    std::snprintf(what, sizeof what, "did not return within %g s (endless loop? SPHKERN_PLUGIN_TIMEOUT sets the bound)",
                  seconds);
    end_for_plugin(call, what);
}

[[noreturn]] void end_for_interrupt(const PluginCall& call)
{
    const int sig = interrupting_signal();
    const char* name = sig == SIGINT    ? "interrupted (SIGINT)"
                       : sig == SIGTERM ? "terminated (SIGTERM)"
                                        : "hung up (SIGHUP)";
    const char* parts[] = {name, " while ", call.plugin(), " was in ", call.function(), ": nothing was written"};
    end_process_with_line(static_cast<int>(ExitCode::interrupted), parts, 6);
}

[[noreturn]] void watch(double seconds)
{
    static Watch watches[watched_threads];
    const int hang_ticks = static_cast<int>(seconds * 1000 / tick.count()) + 1;
    int interrupted_for = 0;
    for (;;) {
        std::this_thread::sleep_for(tick);
        // Plugin code may have taken the signals (signal(SIGINT, SIG_IGN) in W): taken back,
        // where sphkern has them, so that a signal during a long call is seen.
        restore_interrupt_handlers();
        interrupted_for = interrupted() ? interrupted_for + 1 : 0;
        for (int t = 0; t < watched_threads; ++t) {
            const CallSample now = sample_plugin_call(t);
            Watch& w = watches[t];
            w.ticks = now.call && now.sequence == w.sequence ? w.ticks + 1 : 0;
            w.sequence = now.sequence;
            if (!now.call) continue;
            if (w.ticks == long_call_ticks)
                spdlog::debug("{} has been in {} for 1 s", now.call->plugin(), now.call->function());
            if (w.ticks >= hang_ticks) end_for_hang(*now.call, seconds);
            // Inside the same call since before the signal came, and still there.
            if (interrupted_for >= interrupt_ticks && w.ticks >= interrupted_for) end_for_interrupt(*now.call);
        }
    }
}

} // namespace

double plugin_timeout_seconds()
{
    const char* text = std::getenv("SPHKERN_PLUGIN_TIMEOUT");
    double seconds = text ? std::strtod(text, nullptr) : 0;
    return seconds > 0 && seconds < 3600 ? seconds : 10.0;
}

void start_plugin_watchdog()
{
    static std::once_flag once;
    std::call_once(once, [] {
        watch_exit_in_plugin_calls();
        const double seconds = plugin_timeout_seconds();
        try {
            std::thread(watch, seconds).detach();
        } catch (const std::system_error& e) {
            spdlog::warn("no watchdog for plugin calls ({}): a plugin that hangs is not stopped", e.what());
        }
    });
}

} // namespace sphkern
