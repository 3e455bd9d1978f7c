// Which plugin function each thread is inside. A crash, an exit() or a hang there is then
// reported as that plugin's (one line, exit 4) by the fault handlers (plugin_faults) and the
// watchdog (plugin_watchdog), instead of a raw signal or a silent end.
#pragma once

#include <cstdint>
#include <string>

namespace sphkern {

// One function of one plugin, named ahead of time so that a signal handler can print it
// without allocating: "FILE: plugin kernel NAME" and "W".
class PluginCall {
public:
    PluginCall(const std::string& file, const std::string& kernel, const char* function);
    const char* plugin() const { return plugin_.c_str(); }
    const char* function() const { return function_; }

private:
    std::string plugin_;
    const char* function_;
};

// Marks the calling thread as inside `call` for the guard's lifetime. Cheap: a few stores.
class PluginCallGuard {
public:
    explicit PluginCallGuard(const PluginCall& call) noexcept;
    ~PluginCallGuard();
    PluginCallGuard(const PluginCallGuard&) = delete;
    PluginCallGuard& operator=(const PluginCallGuard&) = delete;

private:
    struct CallSlot* slot_;
    const PluginCall* previous_;
};

// The plugin call the calling thread is inside, or null. Async-signal-safe.
const PluginCall* current_plugin_call() noexcept;

// What one watched thread is doing: its call (or null) and how many calls it has begun.
struct CallSample {
    const PluginCall* call = nullptr;
    std::uint64_t sequence = 0;
};
constexpr int watched_threads = 256; // threads beyond these are guarded, but not watched for hangs
CallSample sample_plugin_call(int thread) noexcept;

} // namespace sphkern
