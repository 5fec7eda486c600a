#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace m350::gcode {

// The N labels of one program unit: (label, block) pairs sorted by label, then block. A CAM
// program numbers every line, so this is as large as the program: 8 bytes a label, found by binary
// search (a hash map of vectors took about 100 bytes and an allocation per label).
class LabelIndex {
public:
    // The labelled blocks in file order.
    void build(std::vector<std::pair<std::int32_t, std::uint32_t>> entries);

    // The same labels on blocks `offset` further on (a unit moved into a larger program).
    LabelIndex shifted(std::uint32_t offset) const;

    bool empty() const { return entries_.empty(); }
    std::size_t size() const; // how many different labels
    std::size_t count(std::int32_t label) const { return contains(label) ? 1 : 0; }
    bool contains(std::int32_t label) const;
    // The blocks that carry `label`, in file order.
    std::vector<std::uint32_t> at(std::int32_t label) const;
    // The first block carrying `label` at or after `from`, else the first one (FANUC searches
    // forward, then from the top); nothing when no block carries it.
    std::optional<std::uint32_t> find(std::int32_t label, std::uint32_t from) const;

private:
    using Entry = std::pair<std::int32_t, std::uint32_t>;
    std::pair<std::vector<Entry>::const_iterator, std::vector<Entry>::const_iterator> range(std::int32_t label) const;
    std::vector<Entry> entries_;
};

} // namespace m350::gcode
