#include "support/interruption.hpp"

#include "support/error.hpp"

#include <atomic>
#include <csignal>

namespace sphkern {

namespace {

std::atomic<int> received{0};

extern "C" void on_signal(int sig)
{
    if (received.exchange(sig) != 0) { // a second signal: stop at once
        std::signal(sig, SIG_DFL);
        std::raise(sig);
    }
}

} // namespace

void install_interrupt_handlers()
{
    std::signal(SIGINT, on_signal);
    std::signal(SIGTERM, on_signal);
}

void throw_if_interrupted()
{
    if (int sig = received.load(); sig != 0)
        throw Error(ExitCode::interrupted, sig == SIGINT ? "interrupted (SIGINT): nothing was written"
                                                         : "terminated (SIGTERM): nothing was written");
}

} // namespace sphkern
