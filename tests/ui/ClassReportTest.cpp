// m350-hmi --class-report: a folder of attempts (a folder a trainee, or the trainee in the file's
// name) graded into a CSV and one self-contained HTML page; the page is parsed here as the XML it
// is written as, and its table read back cell by cell.
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QXmlStreamReader>

#include <gtest/gtest.h>

#include <map>

namespace m350::test {

namespace {

const QString kAttempts = QStringLiteral(M350_SOURCE_DIR "/tests/training/attempts/pocket-taught-off/");

// A copy of the attempt without its first-line header: the trainee comes from the folder or file.
void copyWithoutHeader(const QString& from, const QString& to) {
    QFile in(from);
    ASSERT_TRUE(in.open(QIODevice::ReadOnly));
    QByteArray text;
    while (!in.atEnd()) {
        const QByteArray line = in.readLine();
        if (!line.contains("\"attempt\"")) {
            text += line;
        }
    }
    QDir().mkpath(QFileInfo(to).absolutePath());
    QFile out(to);
    ASSERT_TRUE(out.open(QIODevice::WriteOnly));
    out.write(text);
}

struct Cell {
    QString cls;
    QString text;
};

// The rows of table `id`: the first cell's text -> the row's cells.
std::map<QString, std::vector<Cell>> tableRows(const QByteArray& html, const QString& id, QString* error) {
    std::map<QString, std::vector<Cell>> rows;
    QXmlStreamReader xml(html);
    bool inTable = false;
    bool inBody = false;
    std::vector<Cell> row;
    while (!xml.atEnd()) {
        xml.readNext();
        if (xml.isStartElement()) {
            if (xml.name() == QLatin1String("table")) {
                inTable = xml.attributes().value(QLatin1String("id")) == id;
            } else if (inTable && xml.name() == QLatin1String("tbody")) {
                inBody = true;
            } else if (inBody && xml.name() == QLatin1String("tr")) {
                row.clear();
            } else if (inBody && xml.name() == QLatin1String("td")) {
                const QString cls = xml.attributes().value(QLatin1String("class")).toString();
                row.push_back({cls, xml.readElementText(QXmlStreamReader::IncludeChildElements)});
            }
        } else if (xml.isEndElement()) {
            if (inBody && xml.name() == QLatin1String("tr") && !row.empty()) {
                rows[row.front().text] = row;
            } else if (xml.name() == QLatin1String("tbody")) {
                inBody = false;
            } else if (xml.name() == QLatin1String("table")) {
                inTable = false;
            }
        }
    }
    if (xml.hasError()) {
        *error = QStringLiteral("%1 at line %2").arg(xml.errorString()).arg(xml.lineNumber());
    }
    return rows;
}

} // namespace

TEST(ClassReport, GradesAFolderOfAttemptsIntoCsvAndAParsableHtmlTable) {
    QTemporaryDir dir;
    const QString attempts = dir.filePath(QStringLiteral("class"));
    copyWithoutHeader(kAttempts + QStringLiteral("correct.jsonl"), attempts + QStringLiteral("/wang/pocket-taught-off.jsonl"));
    copyWithoutHeader(kAttempts + QStringLiteral("wrong-no-fix.jsonl"), attempts + QStringLiteral("/li/pocket-taught-off-2.jsonl"));
    copyWithoutHeader(kAttempts + QStringLiteral("wrong-y-too.jsonl"), attempts + QStringLiteral("/li/pocket-taught-off-1.jsonl"));
    copyWithoutHeader(kAttempts + QStringLiteral("wrong-y-too.jsonl"), attempts + QStringLiteral("/zhao-pocket-taught-off.jsonl"));
    const QString html = dir.filePath(QStringLiteral("class.html"));
    const QString csv = dir.filePath(QStringLiteral("class.csv"));
    QProcess hmi;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    hmi.setProcessEnvironment(env);
    // one exercise, so that the table has one exercise column
    const QString exercises = dir.filePath(QStringLiteral("exercises"));
    QDir().mkpath(exercises + QStringLiteral("/pocket-taught-off"));
    ASSERT_TRUE(QFile::copy(QStringLiteral(M350_SOURCE_DIR "/resources/exercises/pocket-taught-off/exercise.toml"),
                            exercises + QStringLiteral("/pocket-taught-off/exercise.toml")));
    hmi.start(QStringLiteral(M350_HMI_PATH), {QStringLiteral("--class-report"), attempts, QStringLiteral("--exercises"), exercises,
                                              QStringLiteral("--report-html"), html, QStringLiteral("--report-csv"), csv});
    ASSERT_TRUE(hmi.waitForFinished(120000));
    ASSERT_EQ(hmi.exitCode(), 0) << hmi.readAllStandardError().toStdString();

    QFile csvFile(csv);
    ASSERT_TRUE(csvFile.open(QIODevice::ReadOnly));
    const QStringList lines = QString::fromUtf8(csvFile.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    ASSERT_EQ(lines.size(), 4) << lines.join(QLatin1Char('\n')).toStdString(); // header, li, wang, zhao
    EXPECT_EQ(lines[0], QStringLiteral("trainee,exercise,passed,score,time_s,hints,failed_checks,attempts,file"));
    EXPECT_TRUE(lines[1].startsWith(QStringLiteral("li,pocket-taught-off,no,25,60.0,"))) << lines[1].toStdString();
    EXPECT_TRUE(lines[1].endsWith(QStringLiteral(",2,li/pocket-taught-off-1.jsonl"))) << lines[1].toStdString();
    EXPECT_TRUE(lines[2].startsWith(QStringLiteral("wang,pocket-taught-off,yes,100,60.0,0,,1,"))) << lines[2].toStdString();
    EXPECT_TRUE(lines[3].startsWith(QStringLiteral("zhao,pocket-taught-off,no,25,"))) << lines[3].toStdString();

    QFile htmlFile(html);
    ASSERT_TRUE(htmlFile.open(QIODevice::ReadOnly));
    const QByteArray page = htmlFile.readAll();
    EXPECT_FALSE(page.contains("http://") && page.contains("src=")) << "self-contained: nothing fetched";
    QString error;
    const auto table = tableRows(page, QStringLiteral("class"), &error);
    ASSERT_TRUE(error.isEmpty()) << error.toStdString();
    ASSERT_EQ(table.size(), 3u);
    ASSERT_EQ(table.at(QStringLiteral("wang")).size(), 3u); // trainee, the one exercise, passed count
    EXPECT_EQ(table.at(QStringLiteral("wang"))[1].cls, QStringLiteral("pass"));
    EXPECT_TRUE(table.at(QStringLiteral("wang"))[1].text.contains(QStringLiteral("100 (1:00)")));
    EXPECT_EQ(table.at(QStringLiteral("li"))[1].cls, QStringLiteral("fail"));
    EXPECT_TRUE(table.at(QStringLiteral("li"))[1].text.contains(QStringLiteral("pocket-2-y"))) << table.at(QStringLiteral("li"))[1].text.toStdString();
    EXPECT_EQ(table.at(QStringLiteral("li"))[2].text, QStringLiteral("0"));
    EXPECT_EQ(table.at(QStringLiteral("wang"))[2].text, QStringLiteral("1"));
    EXPECT_TRUE(page.contains("function sortBy")) << "the columns sort by a click";
}

TEST(ClassReport, AnAttemptThatCannotBeGradedIsListedAndExitsTwo) {
    QTemporaryDir dir;
    QFile broken(dir.filePath(QStringLiteral("wang-pocket-taught-off.jsonl")));
    ASSERT_TRUE(broken.open(QIODevice::WriteOnly));
    broken.write("{\"t\":1,\"key\":\"START\"\n");
    broken.close();
    QProcess hmi;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    hmi.setProcessEnvironment(env);
    hmi.start(QStringLiteral(M350_HMI_PATH), {QStringLiteral("--class-report"), dir.path()});
    ASSERT_TRUE(hmi.waitForFinished(60000));
    EXPECT_EQ(hmi.exitCode(), 2);
    const QString out = QString::fromUtf8(hmi.readAllStandardOutput());
    EXPECT_TRUE(out.contains(QStringLiteral("wang,pocket-taught-off,error"))) << out.toStdString();
    EXPECT_TRUE(QString::fromUtf8(hmi.readAllStandardError()).contains(QStringLiteral("wang-pocket-taught-off.jsonl:1:"))) ;
}

} // namespace m350::test
