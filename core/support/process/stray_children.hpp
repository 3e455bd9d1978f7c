// Processes a kernel plugin may leave behind: a daemon forked in its constructor or entry
// point, in the probe's child or in sphkern itself. The command line adopts every orphaned
// descendant (a subreaper, so that a daemon that leaves its session still comes back to
// sphkern) and ends what is left of them when it exits. A library host (Python) keeps its
// process as it is.
#pragma once

namespace sphkern {

// Makes this process the reaper of its orphaned descendants (Linux's PR_SET_CHILD_SUBREAPER).
void adopt_orphans();

// Kills and reaps every child of this process still alive, and those that become its
// children as their parents die, for a few rounds. sphkern's own children (probes, isolated
// calls, gnuplot) are waited for before it exits, so what is left is a plugin's.
void end_stray_children();

} // namespace sphkern
