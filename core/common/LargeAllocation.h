#pragma once

#include <cstddef>
#include <new>

namespace m350 {

// Memory for the big arrays of a parsed program (the blocks of a 200,000-line file, its words).
// Allocations of 2 MB and more are aligned to 2 MB and, on Linux, offered to transparent huge
// pages (madvise), so filling them costs one page fault per 2 MB instead of one per 4 KB: on a
// large program page faults were a third of the parse time. Smaller ones come from operator new.
void* allocateLarge(std::size_t bytes);
void freeLarge(void* memory, std::size_t bytes) noexcept;

// A std::allocator that takes its memory from allocateLarge.
template <class T>
struct LargeAllocator {
    using value_type = T;
    LargeAllocator() = default;
    template <class U>
    LargeAllocator(const LargeAllocator<U>&) noexcept {}

    T* allocate(std::size_t n) {
        if (n > static_cast<std::size_t>(-1) / sizeof(T)) {
            throw std::bad_array_new_length();
        }
        return static_cast<T*>(allocateLarge(n * sizeof(T)));
    }
    void deallocate(T* p, std::size_t n) noexcept { freeLarge(p, n * sizeof(T)); }

    template <class U>
    bool operator==(const LargeAllocator<U>&) const noexcept {
        return true;
    }
};

} // namespace m350
