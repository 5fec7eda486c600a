#include "tests/support/ControllerBackupWriter.h"

#include <bit>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <vector>

namespace m350::testing {

namespace fs = std::filesystem;

namespace {

void writeBytes(const fs::path& file, const std::string& bytes) {
    fs::create_directories(file.parent_path());
    std::ofstream(file, std::ios::binary) << bytes;
}

// The factory values of parameters 0-999 as the bundled catalogue gives them (its `default`
// column, from one controller's default_setting): a whole backup, as a real controller has one.
std::array<double, 1000> catalogueDefaults() {
    std::array<double, 1000> values{};
    std::ifstream in(M350_PARAMETER_CATALOGUE);
    std::string line;
    std::getline(in, line); // the header
    while (std::getline(in, line)) {
        std::vector<std::string> fields;
        std::istringstream row(line);
        for (std::string field; std::getline(row, field, '\t');) {
            fields.push_back(field);
        }
        if (fields.size() < 12 || fields[11].empty()) {
            continue;
        }
        const int n = std::stoi(fields[0]);
        if (n >= 0 && n < 1000) {
            values[static_cast<std::size_t>(n)] = std::stod(fields[11]);
        }
    }
    return values;
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

ControllerBackupWriter ControllerBackupWriter::dualYGantry() {
    ControllerBackupWriter b;
    b.defaults = catalogueDefaults();
    for (auto [n, v] : std::initializer_list<std::pair<int, double>>{
             {0, 50},     {61, 3000},  {62, 500},  {63, 10000}, {64, 12000}, {81, 2},     {82, 24000},
             {92, 2},     {94, 2},     {106, 3},   {107, 500},  {108, 500},  {109, 500},  {114, 1},
             {122, 5},    {123, 5},    {124, -5},  {129, 10},   {161, -9999}, {162, -9999}, {163, -9999},
             {164, -9999}, {165, -9999}, {166, 9999}, {167, 9999}, {168, 9999}, {169, 9999}, {170, 9999},
             {443, 3},    {444, 4},    {489, 1},   {490, 2},    {491, 3},    {492, 4}}) {
        b.defaults[static_cast<std::size_t>(n)] = v;
    }
    b.setting = b.defaults;
    for (auto [n, v] : std::initializer_list<std::pair<int, double>>{
             {61, 2000},  {63, 6000},  {64, 8000},  {76, 1},     {106, 2},    {107, 1500}, {108, 1500},
             {109, 800},  {118, 150},  {127, 1},    {128, 1},    {155, 1},    {161, -2},   {162, -2},
             {163, -150}, {164, -2},   {166, 800},  {167, 1200}, {168, 0},    {169, 1200}, {220, 1},
             {211, 0},    {212, 0},    {491, 1},
             {545, 20},   {546, 1},    {547, 0},    {548, 23},   {549, 1},    {550, 0},    {551, 21},
             {552, 1},    {553, 0},    {578, 10},   {579, 1},    {580, 0},
             {730, 8},    {731, 1},    {732, 1},    {733, 9},    {734, 1},    {735, 1}}) {
        b.setting[static_cast<std::size_t>(n)] = v;
    }
    const double g54[] = {100, 100, -100, 0, 0};
    std::copy(std::begin(g54), std::end(g54), b.coordinate.begin() + 5);
    b.mdiLines = {"G90 G0 X0 Y0", "", "", "", "", ""};
    b.files["slib-g.nc"] = "(slib-g.nc: written for the owner-backup tests in the factory's style)\n"
                           "O501(单轴回零 home one axis: #1 = 0 X, 1 Y, 2 Z)\n"
                           "IF [#1 < 0] + [#1 > 2] GOTO99\n"
                           "#10 = #[1045+#1*3]   (home switch input, params 545 548 551)\n"
                           "#11 = #[1047+#1*3]   (its active level)\n"
                           "#12 = #[607+#1]      (first search speed, params 107-109)\n"
                           "#13 = #[612+#1]*2-1  (direction, params 112-114: -1 negative, 1 positive)\n"
                           "#14 = 10000*#13      (search the whole travel for the switch)\n"
                           "IF #1 == 1 GOTO2\n"
                           "IF #1 == 2 GOTO3\n"
                           "G91 G31 X#14 F#12 P#10 L#11 K0 Q1\n"
                           "G91 G01 X[-2*#13] F#12\n"
                           "G91 G31 X[3*#13] F#618 P#10 L#11 K0 Q1\n"
                           "GOTO9\n"
                           "N2 G91 G31 Y#14 F#12 P#10 L#11 K0 Q1\n"
                           "G91 G01 Y[-2*#13] F#12\n"
                           "G91 G31 Y[3*#13] F#618 P#10 L#11 K0 Q1\n"
                           "GOTO9\n"
                           "N3 G91 G31 Z#14 F#12 P#10 L#11 K0 Q1\n"
                           "G91 G01 Z[-2*#13] F#12\n"
                           "G91 G31 Z[3*#13] F#618 P#10 L#11 K0 Q1\n"
                           "N9 G90\n"
                           "#[880+#1] = #[622+#1]  (the position after homing, params 122-124)\n"
                           "#[1515+#1] = 1\n"
                           "N99 M99\n";
    b.files["slib-m.nc"] = "(slib-m.nc: written for the owner-backup tests in the factory's style)\n"
                           "O10030(M30 程序结束 program end)\n"
                           "M5M9M11\n"
                           "#1506 = 30\n"
                           "#701 = #701 + 1  (总加工数)\n"
                           "#702 = #702 + 1  (加工件数)\n"
                           "M99\n";
    b.files["fndzero.nc"] = "(回零 Go Home: Z first, then X and Y by O501)\n"
                            "M98P501X2\n"
                            "M98P501X0\n"
                            "M98P501X1\n"
                            "(the 4th motor drives the gantry's other side: it takes Y's position)\n"
                            "#883=#881\n"
                            "#1518=1\n";
    b.files["key-2.nc"] = "(K2 润滑: oil the guides for 3 s)\n"
                          "M10\n"
                          "G04 P3000\n"
                          "M11\n"
                          "M30\n";
    b.files["key-3.nc"] = "(K3 浮动对刀: the work's top by the floating block, Z zero of the active system)\n"
                          "#30 = #1078  (the block's input, param 578)\n"
                          "#31 = #1080  (its active level)\n"
                          "IF [#1079 == 0] + [#30 < 1] GOTO1\n"
                          "G91 G31 Z-140 F300 P#30 L#31 K0 Q1\n"
                          "IF #1922 != 2 GOTO1\n"
                          "#1922=0 ;clear probe status before retract\n"
                          "G91 G00 Z2\n"
                          "G91 G31 Z-5 F50 P#30 L#31 K0 Q1\n"
                          "IF #1922 != 2 GOTO1\n"
                          "#100 = #1927\n"
                          "#1922=0 ;clear probe status\n"
                          "#[807+[#578-1]*5] = #100 - #629\n"
                          "G91 G00 Z10\n"
                          "G90\n"
                          "M30\n"
                          "N1 #1503 = 1(浮动对刀失败)\n"
                          "M30\n";
    b.files["eng"] = "msg 1\tStart\n";
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
