#pragma once

#include <cstddef>
#include <iterator>

namespace m350 {

// A forward iterator over a list read by index (`list[i]`), for the lists that keep their items
// in pieces (blocks of a file, shared blocks of a log) and so have no array to point into.
template <class List, class Value> class IndexIterator {
public:
    using iterator_category = std::forward_iterator_tag;
    using value_type = Value;
    using difference_type = std::ptrdiff_t;
    using pointer = const Value*;
    using reference = const Value&;

    IndexIterator(const List* list, std::size_t index) : list_(list), index_(index) {}
    reference operator*() const { return (*list_)[index_]; }
    pointer operator->() const { return &(*list_)[index_]; }
    IndexIterator& operator++() {
        ++index_;
        return *this;
    }
    IndexIterator operator++(int) {
        IndexIterator before = *this;
        ++index_;
        return before;
    }
    bool operator==(const IndexIterator& other) const { return index_ == other.index_; }

private:
    const List* list_;
    std::size_t index_;
};

} // namespace m350
