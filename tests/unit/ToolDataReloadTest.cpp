// The tool data's LinuxCNC side (issue 24): G10 L0 reads tool.tbl again but keeps what the session
// wrote itself (LinuxCNC has already written that to the file), and the random changer's pocket
// swap; the FANUC offset memory C registers over the table's columns.
#include "core/gcode/Dialect.h"
#include "core/params/ParameterTable.h"
#include "core/tools/ToolData.h"
#include "core/tools/ToolTableFile.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace {

using namespace m350;
namespace fs = std::filesystem;

fs::path tableFile(const std::string& name, const std::string& text) {
    fs::path path = fs::path(::testing::TempDir()) / ("m350_reload_" + name + "_" + std::to_string(::getpid()) + ".tbl");
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

TEST(ToolDataReload, TheFileIsReadAgainAndTheSessionsOwnRowsStay) {
    params::ParameterTable parameters;
    const fs::path file = tableFile("again", "T1 P1 Z10\nT2 P2 Z20\n");
    tools::ToolData data(gcode::Dialect::fanuc(), parameters, tools::parseToolTable("T1 P1 Z10\nT2 P2 Z20\n", "t").table);
    data.setSourceFile(file.string());
    ASSERT_TRUE(data.keepsToolTable());
    ASSERT_EQ(data.setZ(1, 11.0), std::nullopt); // the session's G10 L1
    std::ofstream(file, std::ios::binary) << "T1 P1 Z10\nT2 P2 Z22\nT3 P3 Z30\nT4 P4 S1\n"; // edited meanwhile
    std::vector<std::string> skipped;
    ASSERT_EQ(data.reload(skipped), std::nullopt);
    EXPECT_DOUBLE_EQ(data.z(1), 11.0) << "what the session wrote stays";
    EXPECT_DOUBLE_EQ(data.z(2), 22.0) << "the file's edit is read";
    EXPECT_DOUBLE_EQ(data.z(3), 30.0);
    ASSERT_EQ(skipped.size(), 1u);
    EXPECT_NE(skipped[0].find(":4:"), std::string::npos) << skipped[0];
    fs::remove(file);
    EXPECT_NE(data.reload(skipped), std::nullopt) << "a file that cannot be read is said";
}

TEST(ToolDataReload, TheRandomChangerSwapsTheTwoToolsPockets) {
    params::ParameterTable parameters;
    tools::ToolData data(gcode::Dialect::fanuc(), parameters,
                         tools::parseToolTable("T1 P0\nT2 P5\nT3 P7\n", "t").table);
    data.swapPockets(1, 2);
    EXPECT_EQ(data.find(2)->pocket, 0);
    EXPECT_EQ(data.find(1)->pocket, 5);
    data.swapPockets(2, 3);
    EXPECT_EQ(data.find(3)->pocket, 0);
    EXPECT_EQ(data.find(2)->pocket, 7);

    tools::ToolData empty(gcode::Dialect::fanuc(), parameters, tools::parseToolTable("T1 P1\nT2 P2\n", "t").table);
    empty.swapPockets(0, 2); // into an empty spindle: its pocket is left empty
    EXPECT_EQ(empty.find(2)->pocket, 0);
    EXPECT_EQ(empty.find(1)->pocket, 1);
    EXPECT_EQ(empty.table().findPocket(2), nullptr);
}

TEST(ToolDataReload, MemoryCKeepsFourRegistersOverTheRow) {
    params::ParameterTable parameters;
    tools::ToolData data(gcode::Dialect::fanuc(), parameters, tools::parseToolTable("T1 P1 Z100 D10\n", "t").table);
    data.setOffsetMemory(tools::OffsetMemory::C);
    ASSERT_EQ(data.setRegister(tools::OffsetRegister::LengthWear, 1, -0.5), std::nullopt);
    ASSERT_EQ(data.setRegister(tools::OffsetRegister::RadiusWear, 1, 0.25), std::nullopt);
    EXPECT_DOUBLE_EQ(data.lengthOffset(1), 99.5);
    EXPECT_DOUBLE_EQ(data.radiusOffset(1), 5.25);
    EXPECT_DOUBLE_EQ(data.offsetVariable(1), -0.5);    // #2001: H wear
    EXPECT_DOUBLE_EQ(data.offsetVariable(201), 100.0); // #2201: H geometry
    ASSERT_EQ(data.setOffsetVariable(202, 50.0), std::nullopt);
    EXPECT_DOUBLE_EQ(data.z(2), 50.0) << "#2202 made tool 2's row";
    EXPECT_FALSE(data.validOffsetNumber(201));
    data.setOffsetMemory(tools::OffsetMemory::A);
    EXPECT_DOUBLE_EQ(data.offsetVariable(1), 100.0); // memory A: #2001 is the one value
    EXPECT_TRUE(data.validOffsetNumber(400));
}

} // namespace
