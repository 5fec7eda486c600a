#include "core/gcode/MappedFile.h"

#if defined(__unix__)
#include <fcntl.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <mutex>

namespace m350::gcode {

namespace {

// The mapped files the handler may repair; a signal handler can only read lock-free state.
constexpr int kSlots = 64;
struct Region {
    std::atomic<std::uintptr_t> begin{0};
    std::atomic<std::uintptr_t> end{0};
    std::atomic<bool> truncated{false};
};
Region regions[kSlots];
std::mutex slotsMutex;
struct sigaction previousHandler {};

void onBusError(int signal, siginfo_t* info, void* context) {
    const auto address = reinterpret_cast<std::uintptr_t>(info->si_addr);
    for (Region& region : regions) {
        if (address >= region.begin.load() && address < region.end.load()) {
            const auto page = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
            void* at = reinterpret_cast<void*>(address & ~(page - 1));
            // mmap is a system call, safe in a handler: the faulting read is retried and sees zeros
            if (::mmap(at, page, PROT_READ, MAP_PRIVATE | MAP_ANONYMOUS | MAP_FIXED, -1, 0) != MAP_FAILED) {
                region.truncated.store(true);
                return;
            }
        }
    }
    // not ours: what would have happened without this handler
    if ((previousHandler.sa_flags & SA_SIGINFO) != 0 && previousHandler.sa_sigaction) {
        previousHandler.sa_sigaction(signal, info, context);
        return;
    }
    if (previousHandler.sa_handler != SIG_DFL && previousHandler.sa_handler != SIG_IGN && previousHandler.sa_handler) {
        previousHandler.sa_handler(signal);
        return;
    }
    ::signal(SIGBUS, SIG_DFL);
    ::raise(SIGBUS);
}

void installHandler() {
    static std::once_flag once;
    std::call_once(once, [] {
        struct sigaction action {};
        action.sa_sigaction = onBusError;
        action.sa_flags = SA_SIGINFO;
        sigemptyset(&action.sa_mask);
        ::sigaction(SIGBUS, &action, &previousHandler);
    });
}

} // namespace

std::shared_ptr<const MappedFile> MappedFile::map(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) {
        return nullptr;
    }
    struct stat info {};
    std::shared_ptr<const MappedFile> mapped;
    if (::fstat(fd, &info) == 0 && S_ISREG(info.st_mode) && info.st_size > 0) {
        const auto size = static_cast<std::size_t>(info.st_size);
        const int populate = size <= kPopulateBytes ? MAP_POPULATE : 0;
        void* address = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE | populate, fd, 0);
        if (address != MAP_FAILED) {
            mapped = std::make_shared<const MappedFile>(address, size);
            if (mapped->slot_ < 0) {
                mapped.reset(); // no room to guard it: read it instead
            }
        }
    }
    ::close(fd);
    return mapped;
}

MappedFile::MappedFile(void* address, std::size_t size) : address_(address), size_(size) {
    installHandler();
    std::lock_guard<std::mutex> lock(slotsMutex);
    for (int i = 0; i < kSlots; ++i) {
        if (regions[i].end.load() == 0) {
            regions[i].truncated.store(false);
            regions[i].begin.store(reinterpret_cast<std::uintptr_t>(address));
            regions[i].end.store(reinterpret_cast<std::uintptr_t>(address) + size);
            slot_ = i;
            return;
        }
    }
}

MappedFile::~MappedFile() {
    if (slot_ >= 0) {
        std::lock_guard<std::mutex> lock(slotsMutex);
        regions[slot_].end.store(0);
        regions[slot_].begin.store(0);
    }
    ::munmap(address_, size_);
}

bool MappedFile::truncated() const {
    return slot_ >= 0 && regions[slot_].truncated.load();
}

void MappedFile::release(std::size_t from, std::size_t to) const {
    const auto page = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
    const auto base = reinterpret_cast<std::uintptr_t>(address_);
    const std::uintptr_t begin = (base + from + page - 1) / page * page;
    const std::uintptr_t end = (base + std::min(to, size_)) / page * page;
    if (end > begin) {
        ::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_DONTNEED);
    }
}

} // namespace m350::gcode

#else

namespace m350::gcode {

std::shared_ptr<const MappedFile> MappedFile::map(const std::string&) { return nullptr; }
MappedFile::MappedFile(void* address, std::size_t size) : address_(address), size_(size) {}
MappedFile::~MappedFile() = default;
bool MappedFile::truncated() const { return false; }
void MappedFile::release(std::size_t, std::size_t) const {}

} // namespace m350::gcode

#endif
