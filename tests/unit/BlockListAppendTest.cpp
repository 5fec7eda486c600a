// BlockList::append takes another list's memory instead of copying its blocks (the parser adopts
// what a second thread read). Whatever the two sizes, every block must be where its index says,
// and the list must go on growing after it.
#include "core/gcode/BlockList.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace m350 {
namespace {

using gcode::Block;
using gcode::BlockList;

constexpr std::size_t kChunk = BlockList::kChunkSize;

// Blocks told apart by their line.
void fill(BlockList& list, std::size_t count, std::uint32_t firstLine) {
    for (std::size_t i = 0; i < count; ++i) {
        Block block;
        block.location.line = firstLine + static_cast<std::uint32_t>(i);
        list.push_back(block);
    }
}

TEST(BlockListAppend, EveryBlockIsWhereItsIndexSaysForAnySizes) {
    const std::vector<std::size_t> sizes = {0, 1, kChunk - 1, kChunk, kChunk + 1, 3 * kChunk + 17, 30 * kChunk + 5,
                                            70 * kChunk + 3};
    for (std::size_t before : sizes) {
        for (std::size_t appended : sizes) {
            SCOPED_TRACE(std::to_string(before) + " + " + std::to_string(appended));
            BlockList list;
            fill(list, before, 1);
            BlockList other;
            fill(other, appended, 1000000);
            list.append(std::move(other));
            EXPECT_EQ(other.size(), 0u);
            ASSERT_EQ(list.size(), before + appended);
            fill(list, kChunk + 3, 5000000); // the list goes on growing after what it took
            ASSERT_EQ(list.size(), before + appended + kChunk + 3);
            for (std::size_t i = 0; i < list.size(); ++i) {
                const std::uint32_t want = i < before                ? static_cast<std::uint32_t>(1 + i)
                                           : i < before + appended ? static_cast<std::uint32_t>(1000000 + i - before)
                                                                   : static_cast<std::uint32_t>(5000000 + i - before - appended);
                ASSERT_EQ(list[i].location.line, want) << "block " << i;
            }
        }
    }
}

} // namespace
} // namespace m350
