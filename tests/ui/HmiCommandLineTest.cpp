// m350-hmi --help and --version as a user types them on a machine without a display (an SSH
// session, a build server): no Qt platform is opened, the text comes and the exit status is 0.
#include <QProcess>
#include <QProcessEnvironment>

#include <gtest/gtest.h>

namespace m350::test {

namespace {

struct Answer {
    int exitCode = -1;
    QProcess::ExitStatus exitStatus = QProcess::CrashExit;
    QString out;
    QString err;
};

// No QT_QPA_PLATFORM, no X11 or Wayland display: what Qt would need to open a window.
Answer runWithoutDisplay(const QStringList& arguments) {
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    for (const char* name : {"QT_QPA_PLATFORM", "DISPLAY", "WAYLAND_DISPLAY"}) {
        env.remove(QString::fromLatin1(name));
    }
    QProcess hmi;
    hmi.setProcessEnvironment(env);
    hmi.start(M350_HMI_PATH, arguments);
    Answer answer;
    if (!hmi.waitForFinished(30000)) {
        hmi.kill();
        answer.err = "m350-hmi did not finish within 30 s";
        return answer;
    }
    answer.exitCode = hmi.exitCode();
    answer.exitStatus = hmi.exitStatus();
    answer.out = QString::fromUtf8(hmi.readAllStandardOutput());
    answer.err = QString::fromUtf8(hmi.readAllStandardError());
    return answer;
}

} // namespace

TEST(HmiCommandLine, HelpNeedsNoDisplay) {
    for (const char* flag : {"--help", "-h"}) {
        Answer a = runWithoutDisplay({QString::fromLatin1(flag)});
        ASSERT_EQ(a.exitStatus, QProcess::NormalExit) << flag << ": " << a.err.toStdString();
        EXPECT_EQ(a.exitCode, 0) << flag << ": " << a.err.toStdString();
        EXPECT_TRUE(a.out.contains("m350-hmi: the M350 panel")) << a.out.toStdString();
        for (const char* option : {"--config", "--replay", "--screenshot", "--state", "--lang"}) {
            EXPECT_TRUE(a.out.contains(QString::fromLatin1(option))) << option << " missing from:\n"
                                                                       << a.out.toStdString();
        }
        EXPECT_FALSE(a.err.contains("platform plugin")) << a.err.toStdString();
    }
}

TEST(HmiCommandLine, HelpAmongOtherOptionsStillAnswers) {
    Answer a = runWithoutDisplay({"--lang", "en", "--help"});
    ASSERT_EQ(a.exitStatus, QProcess::NormalExit) << a.err.toStdString();
    EXPECT_EQ(a.exitCode, 0) << a.err.toStdString();
    EXPECT_TRUE(a.out.contains("--replay")) << a.out.toStdString();
}

TEST(HmiCommandLine, VersionNeedsNoDisplay) {
    Answer a = runWithoutDisplay({"--version"});
    ASSERT_EQ(a.exitStatus, QProcess::NormalExit) << a.err.toStdString();
    EXPECT_EQ(a.exitCode, 0) << a.err.toStdString();
    EXPECT_TRUE(a.out.trimmed().startsWith(QStringLiteral("m350-hmi " M350_VERSION " (commit "))) << a.out.toStdString();
    EXPECT_TRUE(a.out.trimmed().endsWith(QLatin1Char(')'))) << a.out.toStdString();
}

} // namespace m350::test
