#pragma once

#include "core/gcode/Block.h"
#include "core/gcode/BlockStorage.h"
#include "core/common/IndexIterator.h"

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <memory>
#include <span>
#include <vector>

namespace m350::gcode {

// Re-creates the blocks of a chunk that was dropped after parsing, from the file it came from.
class ChunkReloader {
public:
    virtual ~ChunkReloader() = default;
    // Fills `out` (the chunk's block count) with its blocks; what they refer to goes to `storage`.
    // False when the file no longer reads as it did (it was changed while the program ran).
    virtual bool reload(std::uint32_t chunk, std::span<Block> out, BlockStorage& storage) const = 0;
};

// The blocks of a program by index, in chunks of kChunkSize. A chunk of plain lines of a very large
// program (words with plain numbers, nothing a jump, loop or expression refers to) may be dropped
// once parsed; it is re-parsed from the file when one of its blocks is needed again and kept in a
// small cache, so a 1 GB program runs in bounded memory.
//
// A reference to a block of a dropped chunk stays valid until blocks of kCachedChunks - 1 other
// dropped chunks have been looked up; the executor never holds one that long. Not thread-safe.
class BlockList {
public:
    static constexpr std::uint32_t kChunkBits = 12;
    static constexpr std::uint32_t kChunkSize = 1u << kChunkBits;
    static constexpr std::size_t kCachedChunks = 4;

    BlockList() = default;
    BlockList(BlockList&&) noexcept;
    BlockList& operator=(BlockList&&) noexcept;
    BlockList(const BlockList&) = delete;
    BlockList& operator=(const BlockList&) = delete;
    ~BlockList();

    std::size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }

    const Block& operator[](std::size_t index) const {
        const Block* chunk = chunks_[index >> kChunkBits];
        if (chunk == nullptr) [[unlikely]] {
            chunk = cachedChunk(static_cast<std::uint32_t>(index >> kChunkBits));
        }
        return chunk[index & (kChunkSize - 1)];
    }
    // For the parser, which pairs loops: only blocks of chunks that are kept.
    Block& mutableAt(std::size_t index);
    const Block& at(std::size_t index) const;

    // From now on each chunk has an allocation of its own, so that it can be dropped. Otherwise
    // the allocations grow with the list (as much as it holds, up to 64 chunks): a large program
    // takes few of them, which are offered to huge pages (LargeAllocation).
    void allocateChunksApart() { chunksApart_ = true; }
    // Many blocks are coming (a large file): the first allocation is already one of huge pages,
    // instead of a chunk's 384 KB faulted in 4 KB at a time.
    void expectMany() { expectMany_ = true; }
    void push_back(const Block& block) {
        // Slab memory is raw: the block is constructed in place (Block is trivially copyable).
        std::construct_at(&nextSlot(), block);
        addNextSlot();
    }
    // Where the next block goes (raw memory), for the parser to build it in place; addNextSlot()
    // then adds it. What is written there without addNextSlot() is overwritten by the next block.
    Block& nextSlot() {
        if (size_ == capacity_) [[unlikely]] {
            grow();
        }
        return chunks_[size_ >> kChunkBits][size_ & (kChunkSize - 1)];
    }
    void addNextSlot() { ++size_; }

    // Appends the blocks of `other` (which is left empty) and takes over its memory: blocks are
    // copied only where a chunk of this list would straddle two allocations of `other`, and at
    // both ends, so a list of many chunks is appended in about the time of a few.
    void append(BlockList&& other);

    // Drops a full chunk allocated on its own: its blocks come back from `reloader` when looked
    // up. False (and nothing changes) when the chunk shares its memory with others.
    bool drop(std::uint32_t chunk, std::shared_ptr<const ChunkReloader> reloader);
    std::size_t droppedChunks() const;
    // Whether the chunk, re-parsed, no longer read as it did when the program was loaded.
    bool changedOnDisk(std::size_t index) const;

    using const_iterator = IndexIterator<BlockList, Block>;
    const_iterator begin() const { return {this, 0}; }
    const_iterator end() const { return {this, size_}; }

private:
    struct Slab {
        Block* blocks;
        std::size_t capacity;
    };
    struct CacheSlot {
        std::uint32_t chunk = 0;
        bool used = false;
        std::uint64_t lastUse = 0;
        std::unique_ptr<Block[]> blocks;
        std::unique_ptr<BlockStorage> storage;
    };
    struct Dropped {
        bool dropped = false;
        bool changed = false;
    };

    const Block* cachedChunk(std::uint32_t chunk) const;
    void addSlab(std::size_t blocks);
    Block* newChunk();
    void grow();
    void release() noexcept;

    std::vector<Block*> chunks_; // the chunk's first block; nullptr when dropped and not cached
    std::vector<Slab> slabs_;    // owned memory of the kept chunks
    std::size_t size_ = 0;
    std::size_t capacity_ = 0; // blocks the slabs have room for, from index 0
    bool chunksApart_ = false;
    bool expectMany_ = false;
    mutable std::vector<Dropped> dropped_; // by chunk; empty while none was dropped
    std::shared_ptr<const ChunkReloader> reloader_;
    mutable std::vector<CacheSlot> cache_;
    mutable std::uint64_t clock_ = 0;
};

} // namespace m350::gcode
