// Large per-particle arrays whose pages are first touched by the threads that fill them: a
// vector with this allocator leaves trivial values uninitialised on resize, so the page
// faults (and the kernel's zeroing of each page) are spread over the worker threads instead
// of falling on the one that allocates. Arrays of a huge page or more ask for huge pages:
// with 4 KiB pages, sixteen threads faulting in fresh memory wait on each other in the
// kernel, and the process's exit spends its time returning the pages one by one.
#pragma once

#include "support/process/huge_pages.hpp"
#include "support/process/parallel_for.hpp"

#include <memory>
#include <new>
#include <utility>
#include <vector>

namespace sphkern {

template <class T>
struct FirstTouchAllocator : std::allocator<T> {
    using value_type = T;
    template <class U>
    struct rebind {
        using other = FirstTouchAllocator<U>;
    };
    FirstTouchAllocator() = default;
    template <class U>
    FirstTouchAllocator(const FirstTouchAllocator<U>&) noexcept
    {}

    T* allocate(std::size_t n)
    {
        T* p = std::allocator<T>::allocate(n);
        if (n * sizeof(T) >= huge_page_bytes) advise_huge_pages(p, n * sizeof(T));
        return p;
    }

    template <class U, class... Args>
    void construct(U* p, Args&&... args)
    {
        if constexpr (sizeof...(Args) == 0) ::new (static_cast<void*>(p)) U; // default-initialised: not written
        else ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
};

// Every element must be written before it is read.
template <class T>
using FirstTouchVector = std::vector<T, FirstTouchAllocator<T>>;

// One double per particle (h, V), filled by the threads of a parallel pass.
using ParticleValues = FirstTouchVector<double>;

// value(i) for i in [0, n), written (and so first touched) by `threads` threads.
template <class Value>
ParticleValues fill_particle_values(std::size_t n, int threads, const Value& value)
{
    ParticleValues values(n);
    ParallelFor pass;
    pass.run_blocks(n, particle_block_size, threads, [&](std::size_t, std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) values[i] = value(i);
    });
    return values;
}

} // namespace sphkern
