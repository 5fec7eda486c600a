#pragma once

#include "core/macro/BlockSink.h"

#include <cstddef>
#include <iterator>

namespace m350::interp {

// The words of one letter (G or M) of an evaluated block, in program order, read in place: a block
// holds a handful of words, so skipping the others costs less than copying these out.
class LetterWords {
public:
    class Iterator {
    public:
        using iterator_category = std::forward_iterator_tag;
        using value_type = macro::WordValue;
        using difference_type = std::ptrdiff_t;
        using pointer = const macro::WordValue*;
        using reference = const macro::WordValue&;

        Iterator() = default;
        Iterator(pointer at, pointer end, char letter, std::size_t count)
            : at_(at), end_(end), letter_(letter), left_(count) {
            skip();
        }
        reference operator*() const { return *at_; }
        pointer operator->() const { return at_; }
        Iterator& operator++() {
            if (--left_ == 0) {
                at_ = end_; // the last of them: no need to look through the words after it
                return *this;
            }
            ++at_;
            skip();
            return *this;
        }
        Iterator operator++(int) {
            Iterator before = *this;
            ++*this;
            return before;
        }
        bool operator==(const Iterator& other) const { return at_ == other.at_; }

    private:
        void skip() {
            while (at_ != end_ && at_->letter != letter_) {
                ++at_;
            }
        }
        pointer at_ = nullptr;
        pointer end_ = nullptr;
        char letter_ = 0;
        std::size_t left_ = 0; // words of the letter from at_ on
    };

    LetterWords() = default;
    LetterWords(const macro::EvaluatedBlock& block, char letter, std::size_t count)
        : begin_(block.words.data()), end_(block.words.data() + block.words.size()), letter_(letter), count_(count) {}

    Iterator begin() const { return count_ == 0 ? end() : Iterator(begin_, end_, letter_, count_); }
    Iterator end() const { return Iterator(end_, end_, letter_, 0); }
    std::size_t size() const { return count_; }
    bool empty() const { return count_ == 0; }
    const macro::WordValue& front() const { return *begin(); }

private:
    const macro::WordValue* begin_ = nullptr;
    const macro::WordValue* end_ = nullptr;
    char letter_ = 0;
    std::size_t count_ = 0;
};

} // namespace m350::interp
