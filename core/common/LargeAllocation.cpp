#include "core/common/LargeAllocation.h"

#include <cstdlib>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace m350 {
namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;

bool isLarge(std::size_t bytes) {
    return bytes >= kHugePage;
}

std::size_t roundedToHugePages(std::size_t bytes) {
    return (bytes + kHugePage - 1) / kHugePage * kHugePage;
}

} // namespace

void* allocateLarge(std::size_t bytes) {
    if (!isLarge(bytes)) {
        return ::operator new(bytes);
    }
    void* memory = std::aligned_alloc(kHugePage, roundedToHugePages(bytes));
    if (memory == nullptr) {
        throw std::bad_alloc();
    }
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    // Advice only: where huge pages are off or used up this changes nothing.
    ::madvise(memory, roundedToHugePages(bytes), MADV_HUGEPAGE);
#endif
    return memory;
}

void freeLarge(void* memory, std::size_t bytes) noexcept {
    if (!isLarge(bytes)) {
        ::operator delete(memory, bytes);
        return;
    }
    std::free(memory);
}

} // namespace m350
