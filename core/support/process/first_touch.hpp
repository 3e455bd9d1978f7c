// Large per-particle arrays whose pages are first touched by the threads that fill them: a
// vector with this allocator leaves trivial values uninitialised on resize, so the page
// faults (and the kernel's zeroing of each page) are spread over the worker threads instead
// of falling on the one that allocates.
#pragma once

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
    FirstTouchAllocator(const FirstTouchAllocator<U>&) noexcept {}

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

} // namespace sphkern
