#pragma once

#include "core/common/LargeAllocation.h"

#include <algorithm>
#include <cstddef>
#include <memory>
#include <span>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace m350::gcode {

// Storage for many small runs of T that never move once handed out, so a Block can refer to its
// words, assignments and comment text with spans and views, and parsing a 200,000-line program
// allocates a handful of chunks instead of a few hundred thousand vectors and strings. Chunks
// double from 16 KB up to 2 MB, which then come from allocateLarge (huge pages where available).
template <class T>
class Arena {
    static_assert(std::is_trivially_destructible_v<T>, "an arena never runs destructors");

public:
    Arena() = default;
    Arena(const Arena&) = delete;
    Arena& operator=(const Arena&) = delete;
    Arena(Arena&& other) noexcept { swap(other); }
    Arena& operator=(Arena&& other) noexcept {
        Arena moved(std::move(other));
        swap(moved);
        return *this;
    }
    ~Arena() {
        for (const Chunk& chunk : chunks_) {
            freeLarge(chunk.memory, chunk.bytes);
        }
    }

    // Room for `count` consecutive default-constructed Ts; valid for the arena's lifetime.
    std::span<T> allocate(std::size_t count) {
        if (count == 0) {
            return {};
        }
        if (count > capacity_ - used_) {
            addChunk(count);
        }
        T* at = current_ + used_;
        std::uninitialized_default_construct_n(at, count);
        used_ += count;
        return {at, count};
    }

    // Room for up to `most` Ts at the end of the arena, to be written in place (with
    // std::construct_at) while their count is not yet known; keep() then hands out the first ones.
    // Nothing written there is kept without keep(), and the next reserve or allocate reuses it.
    T* reserve(std::size_t most) {
        if (most > capacity_ - used_) {
            addChunk(most);
        }
        return current_ + used_;
    }
    // The first `count` Ts of the room reserve() gave, constructed by the caller.
    std::span<T> keep(std::size_t count) {
        T* at = current_ + used_;
        used_ += count;
        return {at, count};
    }

    // Many items are coming (a large file): the chunks from now on are the largest ones, in huge
    // pages, instead of doubling up from 16 KB with a page fault per 4 KB.
    void expectMany() { nextChunkBytes_ = kLastChunkBytes; }

    // Where the arena stands, to give back everything allocated after it (the parser drops the
    // words of a chunk of plain lines it will re-parse when they run).
    struct Mark {
        std::size_t chunks = 0;
        std::size_t used = 0;
    };
    Mark mark() const { return {chunks_.size(), used_}; }
    void rewind(Mark mark) noexcept {
        while (chunks_.size() > mark.chunks) {
            freeLarge(chunks_.back().memory, chunks_.back().bytes);
            chunks_.pop_back();
        }
        if (chunks_.empty()) {
            current_ = nullptr;
            capacity_ = 0;
            used_ = 0;
            return;
        }
        current_ = static_cast<T*>(chunks_.back().memory);
        capacity_ = chunks_.back().bytes / sizeof(T);
        used_ = mark.used;
    }

    std::span<const T> copy(std::span<const T> items) {
        std::span<T> room = allocate(items.size());
        std::copy(items.begin(), items.end(), room.begin());
        return room;
    }

private:
    static constexpr std::size_t kFirstChunkBytes = std::size_t{16} << 10;
    static constexpr std::size_t kLastChunkBytes = std::size_t{2} << 20;

    struct Chunk {
        void* memory;
        std::size_t bytes;
    };

    void addChunk(std::size_t atLeast) {
        std::size_t items = std::max(atLeast, std::max<std::size_t>(1, nextChunkBytes_ / sizeof(T)));
        nextChunkBytes_ = std::min(nextChunkBytes_ * 2, kLastChunkBytes);
        chunks_.reserve(chunks_.size() + 1);
        void* memory = allocateLarge(items * sizeof(T));
        chunks_.push_back({memory, items * sizeof(T)});
        current_ = static_cast<T*>(memory);
        capacity_ = items;
        used_ = 0;
    }

    void swap(Arena& other) noexcept {
        std::swap(chunks_, other.chunks_);
        std::swap(current_, other.current_);
        std::swap(capacity_, other.capacity_);
        std::swap(used_, other.used_);
        std::swap(nextChunkBytes_, other.nextChunkBytes_);
    }

    std::vector<Chunk> chunks_;
    T* current_ = nullptr;
    std::size_t capacity_ = 0; // of the current chunk
    std::size_t used_ = 0;     // of the current chunk
    std::size_t nextChunkBytes_ = kFirstChunkBytes;
};

// Text (comments, messages) kept for the program's lifetime.
class TextArena {
public:
    std::string_view store(std::string_view text) {
        std::span<const char> kept = chars_.copy(std::span<const char>(text.data(), text.size()));
        return {kept.data(), kept.size()};
    }
    Arena<char>::Mark mark() const { return chars_.mark(); }
    void rewind(Arena<char>::Mark mark) noexcept { chars_.rewind(mark); }

private:
    Arena<char> chars_;
};

} // namespace m350::gcode
