#pragma once

#include <algorithm>
#include <cstddef>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

namespace m350::gcode {

// Storage for many small runs of T that never move once handed out, so a Block can refer to its
// words, assignments and comment text with spans and views, and parsing a 200,000-line program
// allocates a few hundred chunks instead of a few hundred thousand vectors and strings.
template <class T, std::size_t ChunkSize = 16384>
class Arena {
public:
    Arena() = default;
    Arena(const Arena&) = delete;
    Arena& operator=(const Arena&) = delete;
    Arena(Arena&&) = default;
    Arena& operator=(Arena&&) = default;

    // Room for `count` consecutive default-constructed Ts; valid for the arena's lifetime.
    std::span<T> allocate(std::size_t count) {
        if (count == 0) {
            return {};
        }
        if (count > ChunkSize) {
            // A run longer than a chunk gets storage of its own.
            large_.push_back(std::make_unique<T[]>(count));
            return {large_.back().get(), count};
        }
        if (used_ + count > ChunkSize) {
            chunks_.push_back(std::make_unique<T[]>(ChunkSize));
            used_ = 0;
        }
        std::span<T> room(chunks_.back().get() + used_, count);
        used_ += count;
        return room;
    }

    std::span<const T> copy(std::span<const T> items) {
        std::span<T> room = allocate(items.size());
        std::copy(items.begin(), items.end(), room.begin());
        return room;
    }

private:
    std::vector<std::unique_ptr<T[]>> chunks_;
    std::vector<std::unique_ptr<T[]>> large_;
    std::size_t used_ = ChunkSize; // of the last chunk
};

// Text (comments, messages) kept for the program's lifetime.
class TextArena {
public:
    std::string_view store(std::string_view text) {
        std::span<const char> kept = chars_.copy(std::span<const char>(text.data(), text.size()));
        return {kept.data(), kept.size()};
    }

private:
    Arena<char, 65536> chars_;
};

} // namespace m350::gcode
