#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <utility>

namespace m350 {

// Keeps what a run produces without end (messages, trace lines, DPRNT records) bounded: the first
// pieces go on while their cost fits the head budget, then only the newest pieces whose cost fits
// the tail budget are kept; the ones dropped in between are counted, so a report can say so. The
// caller keeps or writes the head itself (takeIntoHead says where a piece goes); the tail lives here.
template <typename Piece>
class HeadTail {
public:
    struct Kept {
        Piece piece;
        std::size_t cost;
    };

    HeadTail(std::size_t headBudget, std::size_t tailBudget) : headBudget_(headBudget), tailBudget_(tailBudget) {}

    // True when a piece of this cost still belongs to the head (and is counted there). Once one
    // piece did not fit, every later piece goes to the tail, so the head stays the run's beginning.
    bool takeIntoHead(std::size_t cost) {
        if (!full_ && headUsed_ + cost <= headBudget_) {
            headUsed_ += cost;
            return true;
        }
        full_ = true;
        return false;
    }

    void keepInTail(Piece piece, std::size_t cost) {
        tail_.push_back({std::move(piece), cost});
        tailUsed_ += cost;
        while (tailUsed_ > tailBudget_ && !tail_.empty()) {
            tailUsed_ -= tail_.front().cost;
            omittedCost_ += tail_.front().cost;
            ++omitted_;
            tail_.pop_front();
        }
    }

    // Stores a piece wherever it belongs when the caller keeps no head of its own.
    template <typename Head>
    void add(Head& head, Piece piece, std::size_t cost) {
        if (takeIntoHead(cost)) {
            head.push_back(std::move(piece));
        } else {
            keepInTail(std::move(piece), cost);
        }
    }

    const std::deque<Kept>& tail() const { return tail_; }
    std::uint64_t omitted() const { return omitted_; }
    std::uint64_t omittedCost() const { return omittedCost_; }

    void clear() {
        tail_.clear();
        headUsed_ = tailUsed_ = 0;
        omitted_ = omittedCost_ = 0;
        full_ = false;
    }

private:
    std::size_t headBudget_;
    std::size_t tailBudget_;
    std::size_t headUsed_ = 0;
    std::size_t tailUsed_ = 0;
    bool full_ = false;
    std::deque<Kept> tail_;
    std::uint64_t omitted_ = 0;
    std::uint64_t omittedCost_ = 0;
};

} // namespace m350
