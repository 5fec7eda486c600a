#pragma once

// For the tests that compare two ways of reading a program (kept in part, read on two threads):
// the two must give the same block, field by field.

#include "core/gcode/Block.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <string>

namespace m350 {

inline void expectSameBlock(const gcode::Block& a, const gcode::Block& b, std::size_t index) {
    SCOPED_TRACE("block " + std::to_string(index) + " at line " + std::to_string(a.location.line));
    EXPECT_EQ(a.location.file, b.location.file);
    EXPECT_EQ(a.location.line, b.location.line);
    EXPECT_EQ(a.location.column, b.location.column);
    EXPECT_EQ(a.label, b.label);
    EXPECT_EQ(a.programNumber, b.programNumber);
    EXPECT_EQ(a.blockDelete, b.blockDelete);
    EXPECT_EQ(a.programEnd, b.programEnd);
    EXPECT_EQ(a.control, b.control);
    EXPECT_EQ(a.partner, b.partner);
    EXPECT_EQ(a.comment, b.comment);
    EXPECT_EQ(a.assignments.size(), b.assignments.size());
    ASSERT_EQ(a.words.size(), b.words.size());
    for (std::size_t w = 0; w < a.words.size(); ++w) {
        EXPECT_EQ(a.words[w].letter, b.words[w].letter);
        EXPECT_EQ(a.words[w].number, b.words[w].number);
        EXPECT_EQ(a.words[w].value, b.words[w].value);
        EXPECT_EQ(a.words[w].column, b.words[w].column);
    }
}

} // namespace m350
