#include "core/gcode/BlockList.h"

#include "core/common/LargeAllocation.h"

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

namespace m350::gcode {

BlockList::BlockList(BlockList&& other) noexcept
    : chunks_(std::move(other.chunks_)), slabs_(std::move(other.slabs_)), size_(std::exchange(other.size_, 0)),
      capacity_(std::exchange(other.capacity_, 0)), chunksApart_(other.chunksApart_),
      expectMany_(other.expectMany_), dropped_(std::move(other.dropped_)),
      reloader_(std::move(other.reloader_)), cache_(std::move(other.cache_)), clock_(other.clock_) {
    other.slabs_.clear();
    other.chunks_.clear();
}

BlockList& BlockList::operator=(BlockList&& other) noexcept {
    if (this != &other) {
        release();
        chunks_ = std::move(other.chunks_);
        slabs_ = std::move(other.slabs_);
        size_ = std::exchange(other.size_, 0);
        capacity_ = std::exchange(other.capacity_, 0);
        chunksApart_ = other.chunksApart_;
        expectMany_ = other.expectMany_;
        dropped_ = std::move(other.dropped_);
        reloader_ = std::move(other.reloader_);
        cache_ = std::move(other.cache_);
        clock_ = other.clock_;
        other.slabs_.clear();
        other.chunks_.clear();
    }
    return *this;
}

BlockList::~BlockList() { release(); }

void BlockList::release() noexcept {
    for (const Slab& slab : slabs_) {
        freeLarge(slab.blocks, slab.capacity * sizeof(Block));
    }
    slabs_.clear();
}

void BlockList::addSlab(std::size_t blocks) {
    blocks = (blocks + kChunkSize - 1) / kChunkSize * kChunkSize;
    slabs_.reserve(slabs_.size() + 1);
    auto* memory = static_cast<Block*>(allocateLarge(blocks * sizeof(Block)));
    slabs_.push_back({memory, blocks});
    for (std::size_t at = 0; at < blocks; at += kChunkSize) {
        chunks_.push_back(memory + at);
    }
    capacity_ += blocks;
}

Block* BlockList::newChunk() {
    slabs_.reserve(slabs_.size() + 1);
    auto* memory = static_cast<Block*>(allocateLarge(kChunkSize * sizeof(Block)));
    slabs_.push_back({memory, kChunkSize});
    return memory;
}

void BlockList::append(BlockList&& other) {
    if (!other.dropped_.empty() || !dropped_.empty()) {
        throw std::logic_error("a list with dropped chunks is not appended");
    }
    const std::size_t total = other.size_;
    std::size_t from = 0;
    // Fill this list's last chunk, so that the rest starts on a chunk of its own.
    for (; from < total && (size_ & (kChunkSize - 1)) != 0; ++from) {
        std::construct_at(&nextSlot(), other[from]);
        addNextSlot();
    }
    if (from == total) {
        other = BlockList();
        return;
    }
    // Room this list has past its blocks is given up: its chunks come from `other` now.
    chunks_.resize(size_ >> kChunkBits);
    capacity_ = size_;
    auto slabEnd = [&other](const Block* block) -> const Block* {
        for (const Slab& slab : other.slabs_) {
            if (block >= slab.blocks && block < slab.blocks + slab.capacity) {
                return slab.blocks + slab.capacity;
            }
        }
        return block; // not reached: every block of `other` is in one of its slabs
    };
    for (; from < total; from += kChunkSize) {
        const Block* first = &other[from];
        const std::size_t count = std::min<std::size_t>(kChunkSize, total - from);
        // A chunk is kChunkSize consecutive blocks of one allocation (the last one is appended to):
        // where `other` has them so, its memory is taken as it is.
        if (first + kChunkSize <= slabEnd(first)) {
            chunks_.push_back(const_cast<Block*>(first));
        } else {
            Block* chunk = newChunk();
            for (std::size_t k = 0; k < count; ++k) {
                std::construct_at(chunk + k, other[from + k]);
            }
            chunks_.push_back(chunk);
        }
        capacity_ += kChunkSize;
        size_ += count;
    }
    slabs_.insert(slabs_.end(), other.slabs_.begin(), other.slabs_.end());
    other.slabs_.clear();
    other = BlockList();
}

void BlockList::grow() {
    // MDI lines and small programs fit the first chunk; beyond it, allocations of at least 2 MB
    // come in huge pages (a page fault per 2 MB instead of per 4 KB).
    constexpr std::size_t kChunkBytes = kChunkSize * sizeof(Block);
    constexpr std::size_t kHugePageChunks = ((std::size_t{2} << 20) + kChunkBytes - 1) / kChunkBytes;
    constexpr std::size_t kMostChunksAtOnce = 64;
    if (chunksApart_ || (capacity_ == 0 && !expectMany_)) {
        addSlab(kChunkSize);
        return;
    }
    addSlab(std::clamp<std::size_t>(capacity_, kHugePageChunks * kChunkSize, kMostChunksAtOnce * kChunkSize));
}

Block& BlockList::mutableAt(std::size_t index) {
    const std::size_t chunk = index >> kChunkBits;
    if (index >= size_ || chunks_[chunk] == nullptr || (chunk < dropped_.size() && dropped_[chunk].dropped)) {
        throw std::logic_error("block " + std::to_string(index) + " is not kept in memory");
    }
    return chunks_[chunk][index & (kChunkSize - 1)];
}

const Block& BlockList::at(std::size_t index) const {
    if (index >= size_) {
        throw std::out_of_range("block " + std::to_string(index) + " of " + std::to_string(size_));
    }
    return (*this)[index];
}

bool BlockList::drop(std::uint32_t chunk, std::shared_ptr<const ChunkReloader> reloader) {
    const std::size_t first = std::size_t{chunk} << kChunkBits;
    if (first + kChunkSize > size_ || chunks_[chunk] == nullptr) {
        return false; // not full, or already dropped
    }
    auto slab = std::find_if(slabs_.rbegin(), slabs_.rend(), [&](const Slab& s) { return s.blocks == chunks_[chunk]; });
    if (slab == slabs_.rend() || slab->capacity != kChunkSize) {
        return false;
    }
    freeLarge(slab->blocks, slab->capacity * sizeof(Block));
    slabs_.erase(std::next(slab).base());
    chunks_[chunk] = nullptr;
    dropped_.resize(chunks_.size());
    dropped_[chunk].dropped = true;
    if (!reloader_) {
        reloader_ = std::move(reloader);
    }
    return true;
}

std::size_t BlockList::droppedChunks() const {
    return static_cast<std::size_t>(
        std::count_if(dropped_.begin(), dropped_.end(), [](const Dropped& d) { return d.dropped; }));
}

bool BlockList::changedOnDisk(std::size_t index) const {
    const std::size_t chunk = index >> kChunkBits;
    if (chunk >= dropped_.size() || !dropped_[chunk].dropped) {
        return false;
    }
    (void)cachedChunk(static_cast<std::uint32_t>(chunk)); // the answer is known once it is re-read
    return dropped_[chunk].changed;
}

// A dropped chunk: from the cache, or re-parsed into the slot used longest ago. The slot's memory
// is reused, so a long program re-reads chunk after chunk without allocating.
const Block* BlockList::cachedChunk(std::uint32_t chunk) const {
    if (chunk >= dropped_.size() || !dropped_[chunk].dropped) {
        return chunks_[chunk]; // a kept chunk (only a caller's mistake gets here with nullptr)
    }
    ++clock_;
    for (CacheSlot& slot : cache_) {
        if (slot.used && slot.chunk == chunk) {
            slot.lastUse = clock_;
            return slot.blocks.get();
        }
    }
    if (cache_.size() < kCachedChunks) {
        cache_.emplace_back();
        cache_.back().blocks = std::make_unique<Block[]>(kChunkSize);
    }
    CacheSlot& slot = *std::min_element(cache_.begin(), cache_.end(),
                                        [](const CacheSlot& a, const CacheSlot& b) { return a.lastUse < b.lastUse; });
    slot.storage = std::make_unique<BlockStorage>(); // frees what the previous chunk's blocks referred to
    slot.chunk = chunk;
    slot.used = true;
    slot.lastUse = clock_;
    std::span<Block> blocks(slot.blocks.get(), kChunkSize);
    if (!reloader_->reload(chunk, blocks, *slot.storage)) {
        dropped_[chunk].changed = true;
    }
    return slot.blocks.get();
}

} // namespace m350::gcode
