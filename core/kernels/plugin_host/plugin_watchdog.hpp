// A thread that watches the plugin calls in flight. Plugin code never checks sphkern's flags,
// so a call that has not returned within the bound is a hang (one line, exit 4), and a call
// still running a second after SIGINT, SIGTERM or SIGHUP ends the process with exit 130;
// the staging output is removed in both cases.
#pragma once

namespace sphkern {

// Seconds one plugin call (and the probe of a plugin) may take: 10, or SPHKERN_PLUGIN_TIMEOUT.
double plugin_timeout_seconds();

// Starts the watchdog once per process, and registers the exit() check (plugin_faults).
void start_plugin_watchdog();

} // namespace sphkern
