// Transparent huge pages for large arrays read or written in an order unrelated to their
// own (a particle's results go to its place in the file's order): with 4 KiB pages nearly
// every such access misses the TLB once the arrays outgrow its reach (a few MiB), and each
// page is a fault of its own. Only a hint: where the kernel does not follow it, nothing else
// changes.
#pragma once

#include <sys/mman.h>

#include <cstddef>
#include <cstdint>
#include <vector>

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

// v.resize(n), its storage first advised to use huge pages when it spans one at least.
template <class Vector>
void resize_on_huge_pages(Vector& v, std::size_t n)
{
    using T = typename Vector::value_type;
    v.reserve(n);
    if (n * sizeof(T) >= huge_page_bytes) advise_huge_pages(v.data(), n * sizeof(T));
    v.resize(n);
}

} // namespace sphkern
