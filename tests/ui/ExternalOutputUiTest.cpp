// A FANUC program's DPRNT output on the panel: each record in the system log as it is sent, and
// the whole output in the machine folder's dprnt.txt.
#include "PanelHarness.h"

#include "core/config/MachineConfig.h"

#include <QTemporaryDir>

#include <filesystem>

namespace m350::test {

TEST(ExternalOutput, DprntRecordsGoToTheSystemLogAndDprntTxt) {
    QTemporaryDir dir;
    const std::filesystem::path folder = std::filesystem::path(dir.path().toStdString()) / "fanuc-0i";
    std::filesystem::copy(config::bundledMachinesDirectory() + "/fanuc-0i", folder,
                          std::filesystem::copy_options::recursive);
    PanelHarness panel(QString::fromStdString(folder.string()));
    panel.loadProgram("report.nc", "#100=12.5\nPOPEN\nDPRNT[LENGTH*#100[33]]\nDPRNT[DONE]\nPCLOS\nM30\n");
    panel.key("START");
    panel.advance(2.0);
    std::vector<std::string> records;
    for (const config::LogEntry& entry : *panel.session().latest()->log) {
        if (entry.event == "dprnt") {
            records.push_back(entry.detail);
        }
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
}

} // namespace m350::test
