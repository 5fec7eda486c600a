// What a Program page disk lists: the regular files a user can read, hidden ones left out, links
// followed; the system disk only the programs (*.nc in any case); sorted by name, suffix or date.
#include "ui/program/ProgramFiles.h"

#include <gtest/gtest.h>

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStringList>
#include <QTemporaryDir>

#include <filesystem>

namespace m350::test {

namespace {

void write(const QString& path, const QByteArray& content) {
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(content);
}

QStringList names(const QVector<ui::ProgramFiles::Entry>& entries) {
    QStringList out;
    for (const auto& entry : entries) {
        out << entry.name;
    }
    return out;
}

} // namespace

TEST(ProgramFiles, ListsTheReadableFilesOfADiskAsItShowsThem) {
    namespace fs = std::filesystem;
    QTemporaryDir dir;
    const QDir folder(dir.path());
    write(folder.filePath("b.nc"), "G0 X1\n");
    write(folder.filePath("A.NC"), "G0 X10\nM30\n");
    write(folder.filePath("machine.toml"), "name = \"x\"\n");
    write(folder.filePath(".hidden.nc"), "M30\n");
    write(folder.filePath("零件.nc"), "M30\n");
    ASSERT_TRUE(folder.mkdir("sub.nc"));
    const fs::path root = dir.path().toStdString();
    fs::create_symlink(root / "b.nc", root / "link.nc");
    fs::create_symlink(root / "missing.nc", root / "broken.nc");
    const fs::file_time_type now = fs::file_time_type::clock::now();
    fs::last_write_time(root / "b.nc", now - std::chrono::hours(2));
    fs::last_write_time(root / "A.NC", now - std::chrono::hours(1));
    fs::last_write_time(root / "machine.toml", now - std::chrono::hours(3));
    fs::last_write_time(root / "零件.nc", now - std::chrono::hours(4));

    using PF = ui::ProgramFiles;
    EXPECT_EQ(names(PF::list(dir.path(), PF::Disk::System, PF::Sort::Name)),
              (QStringList{"A.NC", "b.nc", "link.nc", "零件.nc"}));
    EXPECT_EQ(names(PF::list(dir.path(), PF::Disk::User, PF::Sort::Name)),
              (QStringList{"A.NC", "b.nc", "link.nc", "machine.toml", "零件.nc"}));
    EXPECT_EQ(names(PF::list(dir.path(), PF::Disk::User, PF::Sort::Suffix)),
              (QStringList{"A.NC", "b.nc", "link.nc", "零件.nc", "machine.toml"}));
    const auto byDate = PF::list(dir.path(), PF::Disk::User, PF::Sort::Date); // newest first; the link is b.nc's time
    EXPECT_EQ(names(byDate), (QStringList{"A.NC", "b.nc", "link.nc", "machine.toml", "零件.nc"}));
    EXPECT_EQ(byDate[0].size, 11);
    EXPECT_EQ(byDate[1].size, 6);
    EXPECT_EQ(byDate[2].size, 6);
    const QDateTime expected = QFileInfo(folder.filePath("A.NC")).lastModified();
    EXPECT_EQ(byDate[0].modified.toMSecsSinceEpoch(), expected.toMSecsSinceEpoch());
    EXPECT_EQ(byDate[0].modified.timeSpec(), expected.timeSpec());
    EXPECT_TRUE(PF::list(folder.filePath("nowhere"), PF::Disk::User, PF::Sort::Name).isEmpty());
}

} // namespace m350::test
