// How a BlockList takes its memory: a small list one chunk at a time, a list told that many blocks
// are coming one huge-page slab from the start (so the first chunks are not faulted in 4 KB pages).
#include "core/gcode/BlockList.h"

#include <gtest/gtest.h>

namespace m350 {
namespace {

using gcode::Block;
using gcode::BlockList;

void fill(BlockList& list, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) {
        Block block;
        block.location.line = static_cast<std::uint32_t>(i + 1);
        list.push_back(block);
    }
}

TEST(BlockListGrowth, ExpectingManyPutsTheFirstChunksInOneSlab) {
    BlockList expecting;
    expecting.expectMany();
    fill(expecting, BlockList::kChunkSize + 1);
    EXPECT_EQ(&expecting[BlockList::kChunkSize], &expecting[0] + BlockList::kChunkSize);
    EXPECT_EQ(expecting[BlockList::kChunkSize].location.line, BlockList::kChunkSize + 1);

    BlockList small;
    fill(small, BlockList::kChunkSize + 1);
    EXPECT_NE(&small[BlockList::kChunkSize], &small[0] + BlockList::kChunkSize);
    EXPECT_EQ(small[BlockList::kChunkSize].location.line, BlockList::kChunkSize + 1);
}

TEST(BlockListGrowth, AMovedListStillExpectsMany) {
    BlockList expecting;
    expecting.expectMany();
    BlockList moved(std::move(expecting));
    fill(moved, BlockList::kChunkSize + 1);
    EXPECT_EQ(&moved[BlockList::kChunkSize], &moved[0] + BlockList::kChunkSize);
}

} // namespace
} // namespace m350
