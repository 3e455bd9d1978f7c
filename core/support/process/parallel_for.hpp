// Splits [0, n) into one contiguous chunk per thread. A worker's exception is carried
// to the caller (the first one wins, the other workers stop at their next check), the
// parts of a thread the system refuses to create run on the threads it allows (a warning
// says so), and an interrupt stops every worker at its next item.
#pragma once

#include "support/error.hpp"
#include "support/process/interruption.hpp"
#include "support/process/worker_pool.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <optional>
#include <string>
#include <system_error>
#include <thread>
#include <type_traits>
#include <vector>

namespace sphkern {

// The block of ParallelFor::run_blocks that the parallel passes over particles use: small
// enough to share a set of 10^5 particles out among 16 threads, large enough that a block's
// bookkeeping is nothing. Sums are added block by block, so their bits depend on it.
inline constexpr std::size_t particle_block_size = std::size_t{1} << 13;

// The threads a request for `requested` gets: every core for 0 or less.
// Said once a process: the system refused a thread (ulimit -u, a container's limit), and the
// work goes on with the threads it has.
void warn_fewer_threads(int threads, const std::string& reason);

inline int worker_threads(int requested)
{
    return requested > 0 ? requested : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

// Calls work(thread, begin, end) on each chunk; `work` should call keep_going() between
// items and return when it is false.
class ParallelFor {
public:
    bool keep_going() const { return !failed_.load(std::memory_order_relaxed) && !interrupted(); }

    template <class Work>
    void run(std::size_t n, int threads, const Work& work)
    {
        threads = std::max(1, threads);
        std::size_t chunk = (n + static_cast<std::size_t>(threads) - 1) / static_cast<std::size_t>(threads);
        auto guarded = [&](int t) {
            std::size_t begin = std::min(n, chunk * static_cast<std::size_t>(t)), end = std::min(n, begin + chunk);
            try {
                work(t, begin, end);
            } catch (...) {
                std::lock_guard lock(mutex_);
                if (!first_error_) first_error_ = std::current_exception();
                failed_ = true;
            }
        };
        if (threads == 1) guarded(0);
        else {
            bool pooled = false;
            try {
                pooled = run_on_worker_pool(threads, guarded);
            } catch (const std::system_error& e) {
                // The pool ran nothing: every part runs here, one after another.
                warn_fewer_threads(threads, e.what());
                for (int t = 0; t < threads; ++t) guarded(t);
                pooled = true;
            }
            if (!pooled) run_on_own_threads(threads, guarded);
        }
        if (first_error_) std::rethrow_exception(first_error_);
        throw_if_interrupted();
    }

    // Calls work(block, begin, end) on the blocks [b * block_size, (b + 1) * block_size) of
    // [0, n), shared out as threads become free. The blocks do not depend on the thread count,
    // so a result assembled block by block (partial sums added in block order) is the same on
    // any number of threads. work(thread, block, begin, end) is told its thread too, for
    // what each thread may keep of its own (integer counts, whose total is the same).
    template <class Work>
    void run_blocks(std::size_t n, std::size_t block_size, int threads, const Work& work)
    {
        const std::size_t blocks = (n + block_size - 1) / block_size;
        std::atomic<std::size_t> next{0};
        const int workers =
            static_cast<int>(std::clamp<std::size_t>(blocks, 1, static_cast<std::size_t>(std::max(1, threads))));
        run(static_cast<std::size_t>(workers), workers, [&](int thread, std::size_t, std::size_t) {
            for (std::size_t b; keep_going() && (b = next.fetch_add(1, std::memory_order_relaxed)) < blocks;) {
                const std::size_t begin = b * block_size, end = std::min(n, (b + 1) * block_size);
                if constexpr (std::is_invocable_v<const Work&, int, std::size_t, std::size_t, std::size_t>)
                    work(thread, b, begin, end);
                else work(b, begin, end);
            }
        });
    }

private:
    // For a nested or concurrent pass, which finds the pool in use.
    template <class Guarded>
    void run_on_own_threads(int threads, const Guarded& guarded)
    {
        std::vector<std::thread> own;
        int t = 1;
        for (; t < threads; ++t) {
            try {
                own.emplace_back(guarded, t);
            } catch (const std::system_error& e) {
                // The parts no thread took run here, each once, as they would have on their own thread.
                warn_fewer_threads(threads, e.what());
                break;
            }
        }
        for (; t < threads; ++t) guarded(t);
        guarded(0);
        for (auto& th : own) th.join();
    }

    std::atomic<bool> failed_{false};
    std::mutex mutex_;
    std::exception_ptr first_error_;
};

// A reduction over [0, n) on `threads` threads with the same bits on any number: add(i, acc)
// adds item i to a block's accumulator (blocks of particle_block_size, each starting from
// `zero`), and merge(total, block) folds the blocks in block order.
template <class Accumulator, class Add, class Merge>
Accumulator parallel_reduce(std::size_t n, int threads, const Accumulator& zero, const Add& add, const Merge& merge)
{
    std::vector<Accumulator> blocks((n + particle_block_size - 1) / particle_block_size, zero);
    ParallelFor pass;
    pass.run_blocks(n, particle_block_size, threads, [&](std::size_t b, std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) add(i, blocks[b]);
    });
    Accumulator total = zero;
    for (const auto& b : blocks) merge(total, b);
    return total;
}

// The sum of term(i) over [0, n), in blocks: the same bits on any thread count.
template <class Term>
double parallel_sum(std::size_t n, int threads, const Term& term)
{
    return parallel_reduce(
        n, threads, 0.0, [&](std::size_t i, double& sum) { sum += term(i); },
        [](double& total, double block) { total += block; });
}

// The first i in [0, n) (the lowest) for which bad(i) holds, none if none: blocks are checked
// in parallel, each up to its first bad item, so the answer is the same on any thread count.
template <class Bad>
std::optional<std::size_t> first_index_where(std::size_t n, int threads, const Bad& bad)
{
    std::vector<std::size_t> first((n + particle_block_size - 1) / particle_block_size, n);
    ParallelFor pass;
    pass.run_blocks(n, particle_block_size, threads, [&](std::size_t block, std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
            if (bad(i)) {
                first[block] = i;
                return;
            }
    });
    for (std::size_t i : first)
        if (i < n) return i;
    return std::nullopt;
}

} // namespace sphkern
