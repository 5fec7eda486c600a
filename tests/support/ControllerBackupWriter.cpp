#include "tests/support/ControllerBackupWriter.h"

#include <bit>
#include <cstdint>
#include <fstream>
#include <sstream>

namespace m350::testing {

namespace fs = std::filesystem;

namespace {

void writeBytes(const fs::path& file, const std::string& bytes) {
    fs::create_directories(file.parent_path());
    std::ofstream(file, std::ios::binary) << bytes;
}

} // namespace

std::string float64File(const double* values, std::size_t count) {
    std::string bytes;
    for (std::size_t i = 0; i < count; ++i) {
        auto bits = std::bit_cast<std::uint64_t>(values[i]);
        for (int b = 0; b < 8; ++b) {
            bytes += static_cast<char>((bits >> (8 * b)) & 0xffu);
        }
    }
    return bytes;
}

std::string mdiBlock(const std::array<std::string, 6>& lines) {
    std::string bytes;
    for (const std::string& line : lines) {
        bytes += line + std::string(120 - line.size(), '\0');
    }
    return bytes;
}

std::string readFile(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

ControllerBackupWriter ControllerBackupWriter::smallRouter() {
    ControllerBackupWriter b;
    // factory values (default_setting), then the owner's machine on top of them
    for (auto [n, v] : std::initializer_list<std::pair<int, double>>{
             {0, 50},     {61, 3000}, {62, 500},  {63, 10000}, {64, 12000}, {81, 1},    {82, 24000},
             {85, 18000}, {89, 0.5},  {106, 2},   {107, 3000}, {108, 3000}, {109, 1500}, {118, 200},
             {129, 10},   {131, 5},   {132, 150}, {800, 1},    {801, 12}}) {
        b.defaults[static_cast<std::size_t>(n)] = v;
    }
    b.setting = b.defaults;
    for (auto [n, v] : std::initializer_list<std::pair<int, double>>{
             {61, 2500},  {62, 400},  {63, 8000},  {64, 9000},  {76, 1},      {78, 1},    {81, 0.5},
             {82, 18000}, {85, 12000}, {89, 0.25}, {106, 1},    {114, 1},     {118, 300}, {127, 1},
             {128, 1},    {129, 7.25}, {130, 1},   {131, 2},    {132, 300},   {135, 12.5}, {136, -40.75},
             {137, -30},  {140, 8},
             {545, 1},    {546, 1},   {547, 1},    {548, 2},    {549, 1},     {550, 1},   {551, 3},
             {552, 1},    {553, 1},   {575, 12},   {576, 1},    {577, 1},     {578, 13},  {579, 1},
             {580, 1},    {599, 14},  {600, 1},    {601, 1},    {620, 7},     {621, 1},   {622, 1},
             {623, 11},   {624, 1},   {625, 1},    {750, 1},    {751, 1},     {752, 1},
             {800, 2},    {801, 6},   {802, 4},    {806, -5.5}, {807, -80},   {808, 600}, {809, 20},
             {811, 5000}, {812, 3000}, {930, -95.125}, {931, -101.5}}) {
        b.setting[static_cast<std::size_t>(n)] = v;
    }
    const double g54[] = {250.5, 120.25, -33.75, 0, 0};
    std::copy(std::begin(g54), std::end(g54), b.coordinate.begin() + 5);
    b.coordinate[10] = 10;   // G55 X
    b.coordinate[11] = 20;   // G55 Y
    b.coordinate[42] = 1.5;  // common offset Z
    b.mdiLines = {"G90 G0 X20 Y10", "#150=#629+1", "M6", "(MDI " + kGbkTest + ")", "", ""};
    b.files["slib-g.nc"] = "(slib-g.nc: written for the import tests in the factory's style)\n"
                           "O20000(T " + kGbkTest + ")\n"
                           "IF [#1301 == 0] + [#1302 == 0] GOTO9\n"
                           "IF [#1 == #1300] GOTO9\n"
                           "G53 Z#1306 F#1312\n"
                           "#1300 = #1\n"
                           "N9 #1503 = 1000\n"
                           "M99\n"
                           "O502(fixed setter, one pass)\n"
                           "G53 Z#641 F#1312\n"
                           "G53 X#635 Y#636 F#1311\n"
                           "G53 Z#637 F#1312\n"
                           "G91 G31 Z-200 F#632 P#1075 L#1077 K0 Q1\n"
                           "G90\n"
                           "#[1430+#1300-1] = #1927\n"
                           "G91 G01 Z#640 F#632\n"
                           "G90\n"
                           "M99\n";
    b.files["slib-m.nc"] = "O10006(M6: empty, as the factory's)\nM99\n";
    b.files["T.nc"] = "T#1504\n";
    b.files["pause.nc"] = "#1503=1(" + kGbkPause + ")\n";
    b.files["cam/cam1.nc"] = "G0 X0 Y0\r\n";
    b.files["cam/cam1.bmp"] = "BM\x36\x00\x00\x00";
    b.files["logo.bmp"] = "BM\x36\x00\x00\x00";
    b.files["drivers/m350io.ko"] = std::string("\x7f" "ELF\x02\x01\x01", 7);
    b.files["ddcs"] = std::string("\x7f" "ELF\x02\x01\x01", 7);
    b.files["eng"] = "msg 1\tStart\n";
    b.files["sys.log"] = "boot\n";
    b.files["simsun.ttf"] = std::string("\x00\x01\x00\x00", 4);
    return b;
}

void ControllerBackupWriter::writeTo(const fs::path& folder) const {
    fs::create_directories(folder);
    writeBytes(folder / "setting", float64File(setting.data(), setting.size()));
    if (withDefaults) {
        writeBytes(folder / "default_setting", float64File(defaults.data(), defaults.size()));
    }
    if (withCoordinate) {
        writeBytes(folder / "coordinate", float64File(coordinate.data(), coordinate.size()));
    }
    if (withMdi) {
        writeBytes(folder / "mdiblock", mdiBlock(mdiLines));
    }
    for (const auto& [name, bytes] : files) {
        writeBytes(folder / name, bytes);
    }
}

} // namespace m350::testing
