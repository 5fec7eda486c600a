// The N labels of a unit: found forward from a block, then from the top, as FANUC searches.
#include "core/gcode/LabelIndex.h"

#include <gtest/gtest.h>

namespace {

using m350::gcode::LabelIndex;

TEST(LabelIndex, FindsForwardThenFromTheTop) {
    LabelIndex labels;
    labels.build({{10, 0}, {20, 1}, {10, 5}, {30, 7}, {10, 9}}); // N10 three times, in file order
    EXPECT_EQ(labels.size(), 3u);
    EXPECT_EQ(labels.at(10), (std::vector<std::uint32_t>{0, 5, 9}));
    EXPECT_EQ(labels.find(10, 0), 0u);
    EXPECT_EQ(labels.find(10, 1), 5u);
    EXPECT_EQ(labels.find(10, 6), 9u);
    EXPECT_EQ(labels.find(10, 10), 0u); // none below: from the top
    EXPECT_EQ(labels.find(30, 8), 7u);
    EXPECT_FALSE(labels.find(40, 0));
    EXPECT_TRUE(labels.contains(20));
    EXPECT_EQ(labels.count(25), 0u);
}

TEST(LabelIndex, ExtremeLabelsSortAndAreFound) {
    LabelIndex labels;
    labels.build({{99999, 3}, {0, 4}, {2147483647, 5}, {-1, 6}});
    EXPECT_EQ(labels.find(2147483647, 0), 5u);
    EXPECT_EQ(labels.find(0, 0), 4u);
    EXPECT_EQ(labels.find(-1, 0), 6u);
    EXPECT_EQ(labels.at(99999), (std::vector<std::uint32_t>{3}));
}

} // namespace
