// m350-hmi: the desktop panel. Builds the session and the window, then either runs the event loop
// or (with --screenshot / --replay / --state) renders in virtual time and exits.
#include "app/hmi/GradeCommand.h"
#include "app/hmi/ReviewCommand.h"
#include "app/hmi/TrainingCommand.h"
#include "app/hmi/HmiOptions.h"
#include "app/hmi/HmiOutputs.h"
#include "app/hmi/Refusal.h"
#include "app/sim/BreakageOptions.h"
#include "core/config/MachineConfig.h"
#include "core/files/ScratchFolder.h"
#include "ui/i18n/Language.h"
#include "ui/pages/ProgramPage.h"
#include "ui/panel/BackupImportFlow.h"
#include "ui/panel/MainWindow.h"
#include "ui/panel/PanelStyle.h"
#include "ui/panel/QuietOffscreen.h"
#include "ui/panel/PanelMeter.h"
#include "ui/session/MachineFolderCopy.h"
#include "ui/replay/Replay.h"
#include "ui/session/MachineSession.h"

#include <CLI/CLI.hpp>
#include <QApplication>
#include <QFile>
#include <QJsonDocument>
#include <QProcess>
#include <QBuffer>
#include <QTemporaryDir>
#include <QTimer>

#include <csignal>
#include <cstdio>
#include <string_view>
#include <variant>

using namespace m350;

namespace {

// --help and --version are answered before any Qt platform is opened: on a machine without a
// display (an SSH session, a build server) the panel still says how to run it.
bool asksForHelpOrVersion(int argc, char** argv) {
    for (int i = 1; i < argc; ++i) {
        const std::string_view argument = argv[i];
        if (argument == "--") {
            return false; // what follows is a file name
        }
        if (argument == "-h" || argument == "--help" || argument == "--version") {
            return true;
        }
    }
    return false;
}

} // namespace

// --measure: run the loaded program in real time and report what the operator would see.
int measure(QApplication& app, ui::MainWindow& window, ui::MachineSession& session, double seconds, qint64 startNs) {
    // what repaints every frame on the page shown: the machine view on 图形显示, else the DRO
    const bool graphics = window.currentPage()->id() == QLatin1String("graphics");
    ui::PanelMeter meter(window.findChild<QWidget*>(graphics ? QStringLiteral("machineView") : QStringLiteral("droMachine0")),
                         startNs);
    QObject::connect(&session, &ui::MachineSession::snapshotReady, &meter, &ui::PanelMeter::onSnapshot);
    window.show();
    session.start();
    constexpr int kWarmUpMs = 500;
    QTimer::singleShot(kWarmUpMs, &meter, [&meter] { meter.begin(); });
    QTimer::singleShot(kWarmUpMs + static_cast<int>(seconds * 1000.0), &app, [&] {
        std::printf("%s\n", qPrintable(meter.reportJson()));
        app.quit();
    });
    return app.exec();
}

int main(int argc, char** argv) {
    if (asksForHelpOrVersion(argc, argv)) {
        return hmi::parseHmiCommandLine(argc, argv).exitStatus;
    }
    const qint64 startNs = ui::steadyNowNs();
    std::signal(SIGPIPE, SIG_IGN); // a FIFO whose reader went away is a write error, said, not a silent death
    // With TZ unset, glibc looks at /etc/localtime again (a stat) at every local-time conversion Qt
    // asks for (the clock, the log's stamps, the file list's dates); naming that same file reads it
    // once. Same zone, same rules; a TZ the user set (even empty: UTC) is left as it is.
    if (!qEnvironmentVariableIsSet("TZ") && QFile::exists(QStringLiteral("/etc/localtime"))) {
        qputenv("TZ", ":/etc/localtime");
    }
    QApplication app(argc, argv); // takes Qt's own options (-platform ...) out of argv first
    QApplication::setApplicationName(QStringLiteral("m350-studio"));
    ui::installQuietOffscreen();
    ui::Language language(app);
    auto parsed = hmi::parseHmiCommandLine(argc, argv);
    if (!parsed.options) {
        return parsed.exitStatus;
    }
    const hmi::HmiOptions& o = *parsed.options;
    QString languageError;
    if (!language.set(QString::fromStdString(o.language), &languageError)) {
        return hmi::refuse(languageError);
    }
    if (o.language == "zh_CN" && !language.fontProblem().isEmpty()) {
        std::fprintf(stderr, "%s\n", qPrintable(language.fontProblem()));
    }
    if (!o.review.empty()) {
        app.setStyleSheet(ui::panelStyleSheet());
        return hmi::reviewCommand(app, o, language);
    }
    if (o.training) {
        app.setStyleSheet(ui::panelStyleSheet());
        return hmi::trainingCommand(app, o, language);
    }
    if (!o.classReport.empty()) {
        return hmi::classReportCommand(o, language);
    }
    if (o.grading()) {
        return hmi::gradeCommand(o, language);
    }
    // The panel writes into its machine folder (MDI lines ...): the bundled machine is never
    // written; a replay or screenshot works on a throwaway copy, the desktop on the user's own.
    QTemporaryDir scratch;
    QString folder = QString::fromStdString(o.configDir);
    if (folder.isEmpty()) {
        QString error;
        auto copy = o.headlessRun() ? ui::copyBundledMachine(scratch.path(), &error) : ui::userMachineFolder(&error);
        if (!copy) {
            return hmi::refuse(error);
        }
        folder = *copy;
        if (o.headlessRun() && !o.eagerReplay) {
            files::setScratchFolder(scratch.path().toStdString()); // gone at exit: nothing there need survive a power cut
        }
    }
    if (auto refused = hmi::refusedOutput(o, folder)) {
        return hmi::refuse(*refused);
    }
    auto loaded = config::loadMachineFolder(folder.toStdString());
    if (auto* error = std::get_if<config::ConfigError>(&loaded)) {
        return hmi::refuse(QString::fromStdString(error->text(ui::Language::messageLanguage())));
    }
    ui::MachineSession::Options sessionOptions;
    sessionOptions.clock = o.headlessRun() ? ui::MachineSession::Clock::Manual : ui::MachineSession::Clock::RealTime;
    sessionOptions.rate = o.rate;
    sessionOptions.panelThread = o.headlessRun() && !o.eagerReplay;
    sessionOptions.homed = !o.unhomed;
    sessionOptions.tool = o.tool;
    sessionOptions.externalOutputLimit = o.dprntLimit;
    try {
        for (const std::string& broken : o.breaks) {
            sessionOptions.toolBreaks.push_back(sim::parseToolBreak(broken));
        }
    } catch (const CLI::ValidationError& e) {
        return hmi::refuse(QString::fromStdString(e.what()), hmi::kExitUsage);
    }
    ui::MachineSession session(std::move(std::get<config::MachineConfig>(loaded)), sessionOptions);
    app.setStyleSheet(ui::panelStyleSheet());
    ui::MainWindow window(session, folder, &language);
    if (auto* programs = dynamic_cast<ui::ProgramPage*>(window.page(ui::PageId::program));
        programs && !o.programs.empty()) {
        programs->setUserFolder(QString::fromStdString(o.programs));
    }
    if (!o.program.empty()) {
        session.loadProgram(QString::fromStdString(o.program));
    }
    if (!o.page.empty()) {
        window.showPage(QString::fromStdString(o.page));
    }
    if (!o.record.empty()) {
        QString error;
        if (!window.startRecording(QString::fromStdString(o.record), &error)) {
            return hmi::refuse(QStringLiteral("--record: %1").arg(error));
        }
    }
    if (o.measure > 0.0) {
        return measure(app, window, session, o.measure, startNs);
    }
    if (!o.headlessRun()) {
        // The import's "switch to this machine": the panel starts again on the new folder.
        QString switchTo;
        window.backupImport().setSwitcher([&app, &switchTo](const QString& machine) {
            switchTo = machine;
            app.quit();
        });
        window.resize(o.width, o.height);
        window.show();
        const int status = app.exec();
        if (QString error = window.stopRecording(); !error.isEmpty()) {
            return hmi::refuse(QStringLiteral("--record: %1").arg(error));
        }
        if (switchTo.isEmpty()) {
            return status;
        }
        const QStringList args{QStringLiteral("--config"), switchTo, QStringLiteral("--lang"), language.current()};
        return QProcess::startDetached(QCoreApplication::applicationFilePath(), args)
                   ? 0
                   : hmi::refuse(QStringLiteral("cannot start the panel again on %1").arg(switchTo));
    }
    window.resize(o.width, o.height);
    window.show();
    ui::settle(session);
    if (!o.replay.empty()) {
        QString error;
        std::vector<ui::ReplayPlace> places;
        const QString replay = QString::fromStdString(o.replay);
        auto actions = ui::readReplay(replay, &error, &places);
        if (!actions) {
            return hmi::refuse(error);
        }
        if (error = ui::playReplay(window, session, *actions, replay, places,
                                    o.eagerReplay ? ui::ReplayLayout::EachAction : ui::ReplayLayout::WhenRead); !error.isEmpty()) {
            return hmi::refuse(error);
        }
    }
    ui::settle(session);
    if (!o.record.empty()) {
        if (QString error = window.stopRecording(); !error.isEmpty()) {
            return hmi::refuse(QStringLiteral("--record: %1").arg(error));
        }
    }
    if (!o.screenshot.empty()) {
        QByteArray png;
        QBuffer buffer(&png);
        buffer.open(QIODevice::WriteOnly);
        if (!window.grab().save(&buffer, hmi::screenshotFormat(o.screenshot)->constData())) {
            return hmi::refuse(language.say(message("hmi_image_failed", {o.screenshot})));
        }
        if (auto error = hmi::writeOutput(o.screenshot, png)) {
            return hmi::refuse(QStringLiteral("--screenshot: %1").arg(*error));
        }
    }
    if (!o.state.empty()) {
        if (auto error = hmi::writeOutput(o.state, QJsonDocument(window.state()).toJson(QJsonDocument::Indented))) {
            return hmi::refuse(QStringLiteral("--state: %1").arg(*error));
        }
    }
    return 0;
}
