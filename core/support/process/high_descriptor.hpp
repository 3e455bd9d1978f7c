// A descriptor moved out of the low range that a plugin's constructor may close wholesale
// (3 to 63 and the like): dup'ed to at least half the process's descriptor limit, the original
// closed. The same descriptor where none is free up there.
#pragma once

namespace sphkern {

int move_out_of_reach(int fd);

} // namespace sphkern
