// A fixed-size array of plain numbers for the block engine's per-particle data: mapped
// anonymously with transparent huge pages requested, and not initialised, so that the
// first touch (which faults the pages in) happens in the threads that fill it.
#pragma once

#include "support/process/huge_pages.hpp"

#include <algorithm>
#include <cstddef>
#include <new>
#include <sys/mman.h>
#include <type_traits>
#include <utility>

namespace sphkern {

template <class T>
class HugeArray {
    static_assert(std::is_trivially_copyable_v<T>, "plain numbers only");

public:
    HugeArray() = default;
    explicit HugeArray(std::size_t n) : size_(n)
    {
        if (n == 0) return;
        bytes_ = (n * sizeof(T) + huge_page_bytes - 1) / huge_page_bytes * huge_page_bytes;
        void* p = ::mmap(nullptr, bytes_, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        if (p == MAP_FAILED) throw std::bad_alloc();
        advise_huge_pages(p, bytes_);
        data_ = static_cast<T*>(p);
    }
    ~HugeArray()
    {
        if (data_) ::munmap(data_, bytes_);
    }
    HugeArray(HugeArray&& other) noexcept { swap(other); }
    HugeArray& operator=(HugeArray&& other) noexcept
    {
        HugeArray moved(std::move(other));
        swap(moved);
        return *this;
    }
    HugeArray(const HugeArray&) = delete;
    HugeArray& operator=(const HugeArray&) = delete;

    T* data() { return data_; }
    const T* data() const { return data_; }
    std::size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    T& operator[](std::size_t i) { return data_[i]; }
    const T& operator[](std::size_t i) const { return data_[i]; }
    T* begin() { return data_; }
    T* end() { return data_ + size_; }
    const T* begin() const { return data_; }
    const T* end() const { return data_ + size_; }

    friend bool operator==(const HugeArray& a, const HugeArray& b)
    {
        return a.size_ == b.size_ && std::equal(a.begin(), a.end(), b.begin());
    }

private:
    void swap(HugeArray& other) noexcept
    {
        std::swap(data_, other.data_);
        std::swap(size_, other.size_);
        std::swap(bytes_, other.bytes_);
    }
    T* data_ = nullptr;
    std::size_t size_ = 0, bytes_ = 0;
};

} // namespace sphkern
