// The arenas behind parsed blocks: what they hand out never moves, whatever comes after it.
#include "core/common/LargeAllocation.h"
#include "core/gcode/Arena.h"
#include "core/gcode/Block.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace {

using namespace m350::gcode;

TEST(Arena, SpansStayValidAcrossChunksAndMoves) {
    Arena<Word> arena;
    std::vector<std::span<Word>> runs;
    // 400,000 words: well past the 2 MB chunks, with runs of 1 to 7 words.
    for (std::uint32_t i = 0; i < 100000; ++i) {
        std::span<Word> run = arena.allocate(1 + i % 7);
        for (Word& w : run) {
            EXPECT_TRUE(w.isNumber()); // default-constructed
            w.number = i;
            w.letter = 'X';
        }
        runs.push_back(run);
    }
    Arena<Word> moved(std::move(arena));
    Arena<Word> assigned;
    assigned.allocate(3);
    assigned = std::move(moved);
    for (std::uint32_t i = 0; i < runs.size(); ++i) {
        ASSERT_EQ(runs[i].size(), 1 + i % 7);
        for (const Word& w : runs[i]) {
            ASSERT_EQ(w.number, i);
            ASSERT_EQ(w.letter, 'X');
        }
    }
}

TEST(Arena, RunLongerThanAChunkAndEmptyRuns) {
    Arena<char> arena;
    EXPECT_TRUE(arena.allocate(0).empty());
    std::span<char> big = arena.allocate(std::size_t{5} << 20);
    big.front() = 'a';
    big.back() = 'z';
    std::span<char> small = arena.allocate(4);
    small[0] = 'b';
    EXPECT_EQ(big.front(), 'a');
    EXPECT_EQ(big.back(), 'z');
}

TEST(Arena, TextIsCopied) {
    TextArena text;
    std::string original = "T[%.0f]";
    std::string_view kept = text.store(original);
    original[0] = 'X';
    EXPECT_EQ(kept, "T[%.0f]");
    EXPECT_TRUE(text.store("").empty());
}

// A large file's words start in a 2 MB chunk: a run that would not fit a first 16 KB chunk
// follows the first one in the same chunk.
TEST(Arena, ExpectingManyStartsWithTheLargestChunk) {
    const std::size_t firstChunkWords = (std::size_t{16} << 10) / sizeof(Word);
    Arena<Word> expecting;
    expecting.expectMany();
    std::span<Word> first = expecting.allocate(1);
    std::span<Word> next = expecting.allocate(firstChunkWords);
    EXPECT_EQ(next.data(), first.data() + 1);

    Arena<Word> doubling;
    std::span<Word> small = doubling.allocate(1);
    std::span<Word> beyond = doubling.allocate(firstChunkWords);
    EXPECT_NE(beyond.data(), small.data() + 1);
}

TEST(LargeAllocation, HugeBlocksAreAlignedAndUsable) {
    m350::LargeAllocator<std::uint64_t> allocator;
    const std::size_t count = (std::size_t{3} << 20) / sizeof(std::uint64_t);
    std::uint64_t* data = allocator.allocate(count);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(data) % (std::uintptr_t{2} << 20), 0u);
    data[0] = 1;
    data[count - 1] = 2;
    EXPECT_EQ(data[0] + data[count - 1], 3u);
    allocator.deallocate(data, count);
    std::vector<int, m350::LargeAllocator<int>> small{1, 2, 3};
    EXPECT_EQ(small[2], 3);
}

} // namespace
