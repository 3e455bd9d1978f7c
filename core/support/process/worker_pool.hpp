// Threads kept between parallel passes. A relaxation runs some twenty passes a step; starting
// every core's thread anew for each cost more than the pass itself on small sets. The pool's
// threads wait for the next pass; one caller uses them at a time, and a caller that finds
// them busy (a nested pass, or a second thread of a library host) starts threads of its own.
#pragma once

#include <functional>

namespace sphkern {

// Runs job(t) for t in [1, threads) on the pool's threads and job(0) on the caller, and
// returns once all have returned. False, with nothing run, when the pool is in use. Throws
// std::system_error when the system refuses a new thread (the pool keeps those it has).
// `job` must not throw.
bool run_on_worker_pool(int threads, const std::function<void(int)>& job);

} // namespace sphkern
