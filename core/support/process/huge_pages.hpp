// Transparent huge pages for large arrays read or written in an order unrelated to their
// own (a particle's results go to its place in the file's order): with 4 KiB pages nearly
// every such access misses the TLB once the arrays outgrow its reach (a few MiB), and each
// page is a fault of its own. Only a hint: where the kernel does not follow it, nothing else
// changes.
#pragma once

#include <sys/mman.h>

#include <cstddef>
#include <cstdint>

namespace sphkern {

inline constexpr std::size_t huge_page_bytes = std::size_t{2} << 20;

// Asks for huge pages for the whole 4 KiB pages inside [data, data + bytes), before their
// first touch.
inline void advise_huge_pages(const void* data, std::size_t bytes)
{
    constexpr std::uintptr_t page = 4096;
    const auto begin = reinterpret_cast<std::uintptr_t>(data);
    const std::uintptr_t lo = (begin + page - 1) / page * page, hi = (begin + bytes) / page * page;
    if (hi > lo) ::madvise(reinterpret_cast<void*>(lo), hi - lo, MADV_HUGEPAGE);
}

} // namespace sphkern
