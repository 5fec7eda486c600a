// A FANUC program's DPRNT output on the panel: each record in the system log as it is sent (also
// past the output's limit), and the output in the machine folder's dprnt.txt.
#include "PanelHarness.h"

#include "core/config/MachineConfig.h"

#include <QTemporaryDir>

#include <filesystem>

namespace m350::test {

namespace {

std::filesystem::path copyOfFanuc0i(const QTemporaryDir& dir) {
    const std::filesystem::path folder = std::filesystem::path(dir.path().toStdString()) / "fanuc-0i";
    std::filesystem::copy(config::bundledMachinesDirectory() + "/fanuc-0i", folder,
                          std::filesystem::copy_options::recursive);
    return folder;
}

std::vector<files::LogEntry> logged(PanelHarness& panel, const std::string& event) {
    std::vector<files::LogEntry> out;
    for (const files::LogEntry& entry : *panel.session().latest()->log) {
        if (entry.event == event) {
            out.push_back(entry);
        }
    }
    return out;
}

// Loads the program and presses START, then lets `seconds` of virtual time pass.
void runOnPanel(PanelHarness& panel, const QString& name, const QByteArray& text, double seconds) {
    panel.loadProgram(name, text);
    panel.key("START");
    panel.advance(seconds);
}

} // namespace

TEST(ExternalOutput, DprntRecordsGoToTheSystemLogAndDprntTxt) {
    QTemporaryDir dir;
    const std::filesystem::path folder = copyOfFanuc0i(dir);
    PanelHarness panel(QString::fromStdString(folder.string()));
    runOnPanel(panel, "report.nc", "#100=12.5\nPOPEN\nDPRNT[LENGTH*#100[33]]\nDPRNT[DONE]\nPCLOS\nM30\n", 2.0);
    std::vector<std::string> records;
    for (const files::LogEntry& entry : logged(panel, "dprnt")) {
        records.push_back(entry.detail);
    }
    ASSERT_EQ(records.size(), 2u);
    EXPECT_EQ(records[0].rfind("LENGTH", 0), 0u) << records[0];
    EXPECT_NE(records[0].find("12.5"), std::string::npos) << records[0];
    EXPECT_EQ(records[1], "DONE");
    QFile file(QString::fromStdString((folder / "dprnt.txt").string()));
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QByteArray text = file.readAll();
    EXPECT_TRUE(text.contains("DONE")) << text.toStdString();
    EXPECT_TRUE(text.contains("12.5")) << text.toStdString();
    EXPECT_TRUE(logged(panel, "dprnt_limit").empty());
}

// dprnt.txt is written at most once a second while a program sends; a panel closed mid-run still
// writes what came last.
TEST(ExternalOutput, APanelClosedMidRunWritesTheLastRecords) {
    QTemporaryDir dir;
    const std::filesystem::path folder = copyOfFanuc0i(dir);
    {
        PanelHarness panel(QString::fromStdString(folder.string()));
        runOnPanel(panel, "late.nc", "POPEN\nDPRNT[FIRST]\nG4 P500\nDPRNT[SECOND]\nG4 P60000\nM30\n", 1.5);
        ASSERT_EQ(logged(panel, "dprnt").size(), 2u);
    }
    QFile file(QString::fromStdString((folder / "dprnt.txt").string()));
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    EXPECT_EQ(file.readAll().toStdString(), "FIRST\nSECOND\n");
}

// 300 records of 13 bytes pass a 1,000-byte limit: dprnt.txt keeps the first and the last ones, and
// the log still gets each of them in order, with one line saying the output reached its limit.
TEST(ExternalOutput, PastTheLimitEveryRecordIsStillLoggedAndTheLogSaysSo) {
    QTemporaryDir dir;
    const std::filesystem::path folder = copyOfFanuc0i(dir);
    ui::MachineSession::Options options;
    options.externalOutputLimit = 1000;
    PanelHarness panel(QString::fromStdString(folder.string()), options);
    runOnPanel(panel, "count.nc", "POPEN\n#1=1\nWHILE[#1LE300]DO1\nDPRNT[RECORD*#1[40]]\n#1=#1+1\nEND1\n"
                                 "PCLOS\nM30\n", 2.0);
    ASSERT_FALSE(panel.session().latest()->status.alarm.has_value())
        << panel.session().latest()->status.alarm->message;
    const std::vector<files::LogEntry> records = logged(panel, "dprnt");
    ASSERT_EQ(records.size(), 300u);
    for (std::size_t i = 0; i < records.size(); ++i) {
        const std::string& text = records[i].detail;
        ASSERT_EQ(text.rfind("RECORD ", 0), 0u) << text;
        EXPECT_EQ(std::stoi(text.substr(7)), static_cast<int>(i + 1)) << text;
    }
    const std::vector<files::LogEntry> limit = logged(panel, "dprnt_limit");
    ASSERT_EQ(limit.size(), 1u);
    EXPECT_EQ(limit[0].detail, "1000 B");
    EXPECT_TRUE(logged(panel, "dprnt_missed").empty());

    QFile file(QString::fromStdString((folder / "dprnt.txt").string()));
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const std::string text = file.readAll().toStdString();
    EXPECT_LT(text.size(), 1200u) << text;
    EXPECT_NE(text.find(records.front().detail + "\n"), std::string::npos) << text;
    EXPECT_NE(text.find(records.back().detail + "\n"), std::string::npos) << text;
    EXPECT_NE(text.find("omitted: the output reached its limit"), std::string::npos) << text;
    EXPECT_EQ(text.find(records[150].detail + "\n"), std::string::npos) << text;
}

} // namespace m350::test
