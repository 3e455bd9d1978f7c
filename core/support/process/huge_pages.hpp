// Transparent huge pages for the large arrays of a particle set that are read or written in
// an order unrelated to their own (a particle's results go to its place in the file's order):
// with 4 KiB pages nearly every such access misses the TLB once the arrays outgrow its reach
// (a few MiB). Only a hint: where the kernel does not follow it, nothing else changes.
#pragma once

#include <sys/mman.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace sphkern {

// v.resize(n), its storage first advised to use huge pages (before the resize touches it).
template <class T>
void resize_on_huge_pages(std::vector<T>& v, std::size_t n)
{
    constexpr std::size_t huge_page = std::size_t{2} << 20, page = 4096;
    v.reserve(n);
    if (n * sizeof(T) >= huge_page) { // the whole pages inside the storage
        const auto begin = reinterpret_cast<std::uintptr_t>(v.data());
        const std::uintptr_t lo = (begin + page - 1) / page * page, hi = (begin + n * sizeof(T)) / page * page;
        ::madvise(reinterpret_cast<void*>(lo), hi - lo, MADV_HUGEPAGE);
    }
    v.resize(n);
}

} // namespace sphkern
