// The machine's libraries parsed once (controller::LibraryCache, gcode::Parser::joinLibraries):
// a second load reuses them, a library edited on disk is parsed again, and a program or MDI line
// loads and runs exactly as when every load parsed the libraries (RunSettings::
// reuseParsedLibraries = false): the same diagnostics in the same order, the same program, the
// same run.
#include "FileText.h"
#include "RunProgram.h"

#include "core/gcode/Program.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace m350;
using namespace m350::test;
using controller::Controller;
namespace fs = std::filesystem;

// Libraries with what joining must move: loops (WHILE/END partners), N labels and GOTOs,
// expressions and assignments, a Modbus statement, a suspect line, a flow finding, an O number
// defined twice, a syntax error on a line no one reaches, and a comment over two lines.
const std::string kGLibrary = lines({
    "// G handlers",
    "O9100(G100)",
    "#110 = #0 * 2 + [#1 + 1]",
    "N5 #111 = #111 + 1",
    "IF [#111 < 3] GOTO5",
    "M99",
});
const std::string kMLibrary = lines({
    "O10150(M150)",
    "#100 = 0",
    "#101 = 0",
    "WHILE [#101 LT 4] DO1",
    "#100 = #100 + #101 * 1.5",
    "#101 = #101 + 1",
    "END1",
    "M99",
    "O10151(M151)",
    "#102 = SQRT[16] + ABS[-2]",
    "GOTO 77",
    "M99",
});
const std::string kOtherLibrary = lines({
    "O500(twice: said unless the main file has its own O500)",
    "#103 = 5",
    "M99",
    "O500",
    "#103 = 6",
    "M99",
    "O501",
    "G1 X[#0 + 1] F1000",
    "MBYTE2DATA[1, 2]",
    "#104 = #0",
    "M99",
    "O502",
    "N1 GOTO1",
    "M99",
    "M30",
    "G1 X1 Y",
    "/* a comment",
    "over two lines */",
});
const std::string kAllTools = lines({"#105 = 7", "M99"});

class LibraryReuse : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        folder_ = fs::path(::testing::TempDir()) / (std::string("m350_libcache_") + info->name());
        fs::remove_all(folder_);
        fs::create_directories(folder_);
        writeText(folder_ / "slib-g.nc", kGLibrary);
        writeText(folder_ / "slib-m.nc", kMLibrary);
        writeText(folder_ / "slib-other.nc", kOtherLibrary);
        writeText(folder_ / "ALL_T.nc", kAllTools);
    }
    void TearDown() override { fs::remove_all(folder_); }

    config::MachineConfig machine() const {
        config::MachineConfig config = m350Machine();
        config.folder = folder_.string();
        config.libraries = {{(folder_ / "slib-g.nc").string(), gcode::FileRole::GLibrary},
                            {(folder_ / "slib-m.nc").string(), gcode::FileRole::MLibrary},
                            {(folder_ / "slib-other.nc").string(), gcode::FileRole::Library}};
        return config;
    }
    std::unique_ptr<Controller> controller(bool reuse) const {
        controller::RunSettings settings;
        settings.reuseParsedLibraries = reuse;
        return std::make_unique<Controller>(machine(), settings);
    }
    std::string program(const std::string& name, const std::string& text) const {
        writeText(folder_ / name, text);
        return (folder_ / name).string();
    }

    fs::path folder_;
};

// Everything a load and a run show: the diagnostics as listed (kind, id, file:line:col), the parsed
// program (files, units, blocks, suspects, which unit an O number finds) and the run's report.
std::string loadAndRun(Controller& c, const std::string& path, bool mdi, const std::string& mdiLine = "") {
    std::ostringstream out;
    const bool loaded = mdi ? c.loadMdi({mdiLine}) : c.loadFile(path);
    out << "loaded " << loaded << "\n";
    for (const gcode::Diagnostic& d : c.diagnostics()) {
        out << static_cast<int>(d.severity) << static_cast<int>(d.kind) << " " << d.messageId << " "
            << gcode::formatDiagnostic(d) << " unreadable " << d.unreadable << " omitted " << d.omitted << "\n";
    }
    const gcode::Program& p = c.program();
    for (const gcode::SourceFile& f : p.files) {
        out << "file " << f.path << " " << static_cast<int>(f.role) << " " << f.encoding << "\n";
    }
    for (const gcode::ProgramUnit& u : p.units) {
        out << "unit O" << u.number << " file " << u.file << " [" << u.begin << "," << u.end << ") labels "
            << u.labels.size() << "\n";
    }
    for (std::size_t b = 0; b < p.blocks.size(); ++b) {
        const gcode::Block& block = p.blocks[b];
        out << b << ": " << block.location.file << ":" << block.location.line << " N" << block.label << " O"
            << block.programNumber << " c" << static_cast<int>(block.control) << " p" << block.partner << " s"
            << block.suspect << " w" << block.words.size() << " a" << block.assignments.size() << "\n";
        if (block.suspect) {
            out << "  suspect " << gcode::formatDiagnostic(p.suspectMessage(static_cast<std::uint32_t>(b))) << "\n";
        }
    }
    for (int number : {500, 501, 502, 9100, 10150, 10151, 10101, 600}) {
        auto unit = p.findUnit(number);
        auto handler = p.findHandler(number, gcode::FileRole::MLibrary);
        out << "O" << number << " -> " << (unit ? static_cast<int>(*unit) : -1) << " handler "
            << (handler ? static_cast<int>(*handler) : -1) << "\n";
        if (unit) {
            for (int label : {1, 5, 77}) {
                auto found = p.findLabel(*unit, label, p.units[*unit].begin);
                out << "  N" << label << " -> " << (found ? static_cast<int>(*found) : -1) << "\n";
            }
        }
    }
    if (!loaded) {
        return out.str();
    }
    const controller::RunReport report = c.run();
    out << "status " << static_cast<int>(report.status) << " blocks " << report.blocks << " time " << report.simTime
        << "\n";
    if (report.alarm) {
        out << "alarm " << alarmKey(report.alarm->code) << " " << report.alarm->file << ":" << report.alarm->line
            << ":" << report.alarm->column << " " << report.alarm->message << "\n";
    }
    for (int axis = 0; axis < report.machine.size(); ++axis) {
        out << report.machine[axis] << " ";
    }
    out << "\n";
    for (const std::string& m : report.messages) {
        out << "message " << m << "\n";
    }
    for (int number = 100; number <= 111; ++number) {
        const macro::Value v = c.variable(number);
        out << "#" << number << "=" << (v.vacant ? std::string("vacant") : std::to_string(v.number)) << " ";
    }
    return out.str() + "\n";
}

TEST_F(LibraryReuse, ASecondLoadReusesTheParsedLibraries) {
    auto c = controller(true);
    EXPECT_EQ(c->libraryParses(), 0u);
    ASSERT_TRUE(c->loadMdi({"M150"})) << loadAndRun(*c, "", true, "M150");
    EXPECT_EQ(c->libraryParses(), 1u);
    c->run();
    EXPECT_DOUBLE_EQ(c->variable(100).number, 9.0); // 0 + 1.5 + 3 + 4.5
    for (const char* line : {"G0 X1", "G0 X-1", "M98 P9100", "M151", "M101"}) {
        c->loadMdi({line});
        c->run();
    }
    EXPECT_EQ(c->libraryParses(), 1u);
    EXPECT_DOUBLE_EQ(c->variable(105).number, 7.0); // M101 ran ALL_T.nc, joined with the libraries
    const std::string path = program("main.nc", lines({"M98 P500", "M30"}));
    ASSERT_TRUE(c->loadFile(path));
    c->run();
    EXPECT_DOUBLE_EQ(c->variable(103).number, 5.0);
    EXPECT_EQ(c->libraryParses(), 1u);

    // A controller that parses at every load never fills the cache.
    auto every = controller(false);
    every->loadMdi({"M150"});
    every->loadMdi({"M150"});
    EXPECT_EQ(every->libraryParses(), 0u);
}

TEST_F(LibraryReuse, ALibraryEditedOnDiskIsParsedAgain) {
    auto c = controller(true);
    auto every = controller(false); // the same history, parsing at every load
    const auto both = [&](const std::string& line) {
        const std::string seen = loadAndRun(*c, "", true, line);
        EXPECT_EQ(seen, loadAndRun(*every, "", true, line)) << line;
        return seen;
    };
    both("M98 P500");
    EXPECT_DOUBLE_EQ(c->variable(103).number, 5.0);
    const fs::path library = folder_ / "slib-other.nc";
    const auto stamp = fs::last_write_time(library);
    std::string edited = kOtherLibrary;
    edited.replace(edited.find("#103 = 5"), 8, "#103 = 8"); // the same size and, below, the same time
    writeText(library, edited);
    fs::last_write_time(library, stamp);
    both("M98 P500");
    EXPECT_DOUBLE_EQ(c->variable(103).number, 8.0);
    EXPECT_EQ(c->libraryParses(), 2u);
    both("M98 P500");
    EXPECT_EQ(c->libraryParses(), 2u);

    // A syntax error put into a library stops the load, named where it is, as without the cache.
    std::string broken = kMLibrary;
    broken.replace(broken.find("ABS[-2]"), 7, "ABS[-2 ");
    writeText(folder_ / "slib-m.nc", broken);
    const std::string stopped = both("M150");
    EXPECT_NE(stopped.find("loaded 0"), std::string::npos) << stopped;
    EXPECT_NE(stopped.find("slib-m.nc:10:"), std::string::npos) << stopped;
    EXPECT_EQ(c->libraryParses(), 3u);
    writeText(folder_ / "slib-m.nc", kMLibrary);
    both("M150");

    // A library gone: the same read error, in the same place among the findings.
    fs::remove(folder_ / "slib-g.nc");
    const std::string gone = both("M150");
    EXPECT_NE(gone.find("slib-g.nc"), std::string::npos) << gone;
    writeText(folder_ / "slib-g.nc", kGLibrary);
    both("M150");
    EXPECT_EQ(c->libraryParses(), 4u); // back as it was parsed: nothing to parse again
    // ALL_T.nc gone and back: the hook is left out, then joined again.
    fs::remove(folder_ / "ALL_T.nc");
    EXPECT_NE(both("M101").find("invalid_word"), std::string::npos);
    writeText(folder_ / "ALL_T.nc", kAllTools);
    both("M101");
    EXPECT_DOUBLE_EQ(c->variable(105).number, 7.0);
    EXPECT_EQ(c->libraryParses(), 6u);
}

TEST_F(LibraryReuse, ProgramsLoadAndRunAsWhenEveryLoadParsedTheLibraries) {
    std::string manyErrors; // findings near the bound: joining must give way to parsing
    for (int i = 0; i < 1995; ++i) {
        manyErrors += "G1 X1 Y\n";
    }
    const std::vector<std::string> programs = {
        lines({"#1 = 2", "G65 P501 A3", "M98 P9100", "M150", "M151", "M101", "M98 P500", "M98 P600", "M30"}),
        // its own O500 wins, and the libraries' O500 defined twice is then not said
        lines({"M98 P500", "M30", "O500", "#103 = 9", "M99"}),
        lines({"O500", "#103 = 1", "M99", "O500", "M99", "O10150", "#100 = 42", "M99"}),
        lines({"M98 P501", "M30"}),
        lines({"#1 = [", "M30"}),
        lines({"WHILE [1] DO1", "M30"}),
        manyErrors,
        manyErrors + manyErrors,
        "",
    };
    int index = 0;
    for (const std::string& text : programs) {
        SCOPED_TRACE("program " + std::to_string(index));
        const std::string path = program("main" + std::to_string(index++) + ".nc", text);
        auto reused = controller(true);
        auto every = controller(false);
        // the libraries parsed before (the same history for both): the program joins them
        EXPECT_EQ(loadAndRun(*reused, "", true, "G0 X1"), loadAndRun(*every, "", true, "G0 X1"));
        EXPECT_EQ(loadAndRun(*reused, path, false), loadAndRun(*every, path, false));
        EXPECT_EQ(loadAndRun(*reused, path, false), loadAndRun(*every, path, false));
        EXPECT_EQ(reused->libraryParses(), 1u);
    }
    // MDI lines, and a library loaded as the program itself.
    auto reused = controller(true);
    auto every = controller(false);
    for (const char* line : {"M150", "G65 P501 A2", "M98 P9100", "#1 = [", "M101", "M98 P600"}) {
        SCOPED_TRACE(line);
        EXPECT_EQ(loadAndRun(*reused, "", true, line), loadAndRun(*every, "", true, line));
    }
    const std::string library = (folder_ / "slib-other.nc").string();
    EXPECT_EQ(loadAndRun(*reused, library, false), loadAndRun(*every, library, false));
    const std::string hook = (folder_ / "ALL_T.nc").string();
    EXPECT_EQ(loadAndRun(*reused, hook, false), loadAndRun(*every, hook, false));
}

// The bundled machine's own libraries (its slib-g.nc, slib-m.nc, slib-probe.nc): MDI lines that
// run their handlers give the same run either way.
TEST(LibraryReuseBundled, MdiLinesRunAsWhenEveryLoadParsedTheLibraries) {
    controller::RunSettings reuse;
    controller::RunSettings every;
    every.reuseParsedLibraries = false;
    Controller a(bundledMachine(), reuse);
    Controller b(bundledMachine(), every);
    for (const char* line : {"G0 X10 Y10", "M150", "M151", "G91 G1 X1 F500", "M152", "M153", "G90"}) {
        SCOPED_TRACE(line);
        EXPECT_EQ(loadAndRun(a, "", true, line), loadAndRun(b, "", true, line));
    }
    EXPECT_EQ(a.libraryParses(), 1u);
}

} // namespace

namespace {

std::chrono::system_clock::time_point anHourOn() { return std::chrono::system_clock::now() + std::chrono::hours(1); }

} // namespace

// A library is not read again while its stat is what it was at the read that matched and it was
// settled then (changed well before); an edit that keeps its size and time stamp, a file renamed
// over it, or a file changed just before the read is read again.
TEST_F(LibraryReuse, SettledFilesAreNotReadAgainUntilTheirStatChanges) {
    const fs::path library = folder_ / "stamped.nc";
    const std::string text = "O9010\n#100 = 1\nM99\n";
    writeText(library, text);
    const std::vector<controller::LibraryCache::File> files{{library.string(), gcode::FileRole::GLibrary, -1}};

    controller::LibraryCache later(&anHourOn); // the file's change is an hour old at every read
    const auto first = later.get(gcode::Dialect::m350(), files);
    ASSERT_TRUE(first);
    EXPECT_EQ(later.reads(), 1u);
    EXPECT_EQ(later.get(gcode::Dialect::m350(), files), first);
    EXPECT_EQ(later.reads(), 1u) << "settled and unchanged: not read";

    const auto stamp = fs::last_write_time(library);
    writeText(library, "O9010\n#100 = 2\nM99\n"); // the same size, the time stamp put back
    fs::last_write_time(library, stamp);
    const auto edited = later.get(gcode::Dialect::m350(), files);
    EXPECT_EQ(later.reads(), 2u);
    EXPECT_EQ(later.parses(), 2u);
    EXPECT_NE(edited, first);

    const fs::path copy = folder_ / "copy.nc"; // the same text renamed over it: another file
    writeText(copy, "O9010\n#100 = 2\nM99\n");
    fs::rename(copy, library);
    EXPECT_EQ(later.get(gcode::Dialect::m350(), files), edited);
    EXPECT_EQ(later.reads(), 3u);
    EXPECT_EQ(later.parses(), 2u) << "read the same: not parsed again";
    EXPECT_EQ(later.get(gcode::Dialect::m350(), files), edited);
    EXPECT_EQ(later.reads(), 3u);

    controller::LibraryCache now; // the file changed a moment ago: read at every use
    ASSERT_TRUE(now.get(gcode::Dialect::m350(), files));
    ASSERT_TRUE(now.get(gcode::Dialect::m350(), files));
    EXPECT_EQ(now.reads(), 2u);
    EXPECT_EQ(now.parses(), 1u);
}
