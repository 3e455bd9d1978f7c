#include "support/process/worker_pool.hpp"

#include <pthread.h>

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>

namespace sphkern {

namespace {

struct WorkerPool {
    std::atomic<bool> busy{false};
    std::mutex mutex;
    std::condition_variable wake, finished;
    int workers = 0;        // threads 1 .. workers
    int taking_part = 0;    // of this pass: threads 1 .. taking_part - 1
    int running = 0;        // of this pass, not yet returned
    std::uint64_t pass = 0; // counts the passes, so that a woken thread knows a new one came
    const std::function<void(int)>* job = nullptr;

    // `seen`: the last pass before this thread started.
    void serve(int index, std::uint64_t seen)
    {
        std::unique_lock lock(mutex);
        for (;;) {
            wake.wait(lock, [&] { return pass != seen; });
            seen = pass;
            if (index >= taking_part) continue;
            const auto* work = job;
            lock.unlock();
            (*work)(index);
            lock.lock();
            if (--running == 0) finished.notify_one();
        }
    }

    // Threads up to `count`, with the mutex held; those started stay when one is refused.
    void grow(int count)
    {
        while (workers < count) {
            std::thread([this, index = workers + 1, seen = pass] { serve(index, seen); }).detach();
            ++workers;
        }
    }
};

// Never destroyed: its threads wait until the process ends. A forked child has none of them
// and makes a pool of its own.
std::atomic<WorkerPool*> the_pool{nullptr};

WorkerPool& pool()
{
    static const int forgets_in_child = pthread_atfork(nullptr, nullptr, [] { the_pool.store(nullptr); });
    (void)forgets_in_child;
    WorkerPool* existing = the_pool.load(std::memory_order_acquire);
    if (existing) return *existing;
    auto* made = new WorkerPool;
    if (the_pool.compare_exchange_strong(existing, made, std::memory_order_acq_rel)) return *made;
    delete made; // another thread made it first
    return *existing;
}

} // namespace

bool run_on_worker_pool(int threads, const std::function<void(int)>& job)
{
    WorkerPool& p = pool();
    if (p.busy.exchange(true, std::memory_order_acquire)) return false;
    struct Release {
        WorkerPool& p;
        ~Release() { p.busy.store(false, std::memory_order_release); }
    } release{p};
    {
        std::lock_guard lock(p.mutex);
        p.grow(threads - 1);
        p.job = &job;
        p.taking_part = threads;
        p.running = threads - 1;
        ++p.pass;
    }
    p.wake.notify_all();
    job(0);
    std::unique_lock lock(p.mutex);
    p.finished.wait(lock, [&] { return p.running == 0; });
    return true;
}

} // namespace sphkern
