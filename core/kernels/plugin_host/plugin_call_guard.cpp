#include "kernels/plugin_host/plugin_call_guard.hpp"

#include "kernels/plugin_host/plugin_faults.hpp"
#include "support/text/printable_text.hpp"

#include <atomic>
#include <csignal>
#include <cstdlib>

namespace sphkern {

// One cache line each: the threads of a pass write their own slot around every plugin call,
// and slots sharing a line made each of those writes take the line from the other threads.
struct alignas(64) CallSlot {
    std::atomic<const PluginCall*> call{nullptr};
    std::atomic<std::uint64_t> sequence{0};
    std::atomic<bool> taken{false};
};

namespace {

CallSlot watched[watched_threads];
thread_local CallSlot* my_slot = nullptr; // trivial: cheap to reach, and from a signal handler
thread_local CallSlot unwatched;          // for a thread that found every watched slot taken

// A stack for the fault handler, so that a plugin that overflows its stack is still reported.
constexpr std::size_t handler_stack_bytes = 64 * 1024;

// Gives the slot and the handler stack back when the thread ends. A thread cannot end inside a
// plugin call unless the plugin ended it: exit() runs these destructors before the atexit handlers.
struct ThreadRelease {
    void* stack = nullptr;
    ~ThreadRelease()
    {
        if (const PluginCall* call = my_slot ? my_slot->call.load() : nullptr)
            end_for_plugin(*call, "called exit() or pthread_exit()");
        if (stack) {
            stack_t off{};
            off.ss_flags = SS_DISABLE;
            ::sigaltstack(&off, nullptr);
            std::free(stack);
        }
        if (my_slot && my_slot != &unwatched) {
            my_slot->call.store(nullptr);
            my_slot->taken.store(false);
        }
    }
};
thread_local ThreadRelease release;

void give_thread_a_handler_stack(ThreadRelease& owner)
{
    stack_t current{};
    if (::sigaltstack(nullptr, &current) != 0 || !(current.ss_flags & SS_DISABLE)) return; // one is there
    void* memory = std::malloc(handler_stack_bytes);
    if (!memory) return;
    stack_t mine{};
    mine.ss_sp = memory;
    mine.ss_size = handler_stack_bytes;
    if (::sigaltstack(&mine, nullptr) != 0) return std::free(memory);
    owner.stack = memory;
}

CallSlot* claim_slot()
{
    give_thread_a_handler_stack(release); // also makes the thread release its slot when it ends
    for (auto& slot : watched) {
        bool expected = false;
        if (slot.taken.compare_exchange_strong(expected, true)) return my_slot = &slot;
    }
    return my_slot = &unwatched;
}

} // namespace

PluginCall::PluginCall(const std::string& file, const std::string& kernel, const char* function)
    : plugin_(printable_text(file) + ": plugin kernel " + printable_text(kernel)), function_(function)
{}

PluginCallGuard::PluginCallGuard(const PluginCall& call) noexcept : slot_(my_slot ? my_slot : claim_slot())
{
    previous_ = slot_->call.load(std::memory_order_relaxed);
    slot_->sequence.store(slot_->sequence.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed);
    slot_->call.store(&call, std::memory_order_release);
}

PluginCallGuard::~PluginCallGuard() { slot_->call.store(previous_, std::memory_order_release); }

const PluginCall* current_plugin_call() noexcept
{
    return my_slot ? my_slot->call.load(std::memory_order_acquire) : nullptr;
}

CallSample sample_plugin_call(int thread) noexcept
{
    const CallSlot& slot = watched[thread];
    if (!slot.taken.load(std::memory_order_relaxed)) return {};
    return {slot.call.load(std::memory_order_acquire), slot.sequence.load(std::memory_order_relaxed)};
}

} // namespace sphkern
