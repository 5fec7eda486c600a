// m350-hmi: the desktop panel. Builds the session and the window, then either runs the event loop
// or (with --screenshot / --replay / --state) renders in virtual time and exits.
#include "app/hmi/HmiOptions.h"
#include "app/sim/BreakageOptions.h"
#include "core/config/MachineConfig.h"
#include "core/files/OutputFile.h"
#include "core/files/OutputGuard.h"
#include "ui/i18n/Language.h"
#include "ui/pages/ProgramPage.h"
#include "ui/panel/BackupImportFlow.h"
#include "ui/panel/MainWindow.h"
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
#include <QImageWriter>
#include <QTemporaryDir>
#include <QTimer>

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string_view>
#include <variant>

using namespace m350;

namespace {

int fail(const QString& message, int status = 2) {
    std::fprintf(stderr, "m350-hmi: %s\n", qPrintable(message));
    return status;
}

QString imageSuffixes() {
    QStringList suffixes;
    for (const QByteArray& format : QImageWriter::supportedImageFormats()) {
        suffixes << QString::fromLatin1(format);
    }
    return suffixes.join(QStringLiteral(", "));
}

// The image format --screenshot writes: its suffix's (.png, .jpg ...), PNG for a name without one
// or a device; nullopt for a suffix that is no image format (`--screenshot notes.txt`).
std::optional<QByteArray> screenshotFormat(const std::string& path) {
    std::error_code ec;
    const std::filesystem::path file(path);
    if (!file.has_extension() || (std::filesystem::exists(file, ec) && !std::filesystem::is_regular_file(file, ec))) {
        return QByteArray("png");
    }
    const QByteArray suffix = QByteArray::fromStdString(file.extension().string().substr(1)).toLower();
    if (QImageWriter::supportedImageFormats().contains(suffix)) {
        return suffix;
    }
    return std::nullopt;
}

// The file written whole (a temp file renamed over it) or a device written as one; why not, else
// nullopt.
std::optional<QString> writeOutput(const std::string& path, const QByteArray& bytes) {
    if (auto problem = files::writeOutputFile(path, std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())))) {
        return QString::fromStdString(*problem);
    }
    return std::nullopt;
}

// The panel's own outputs never land on what it reads or owns (issue 26, "Nothing lost"): the
// loaded program, the replay being played, the machine folder; nor on a folder, a socket or a
// disk. Two outputs on one file would leave only the last. Said before the panel starts.
std::optional<QString> refusedOutput(const hmi::HmiOptions& o, const QString& folder) {
    std::vector<files::GuardedPath> guarded{{"the machine folder", folder.toStdString(), true}};
    if (!o.program.empty()) {
        guarded.push_back({"the loaded program", o.program, false});
    }
    if (!o.replay.empty()) {
        guarded.push_back({"the replay being played", o.replay, false});
    }
    std::vector<std::pair<std::string, std::string>> outputs; // option, path
    for (const auto& [option, path] : {std::pair{"--state", &o.state}, {"--screenshot", &o.screenshot}, {"--record", &o.record}}) {
        if (!path->empty()) {
            outputs.emplace_back(option, *path);
        }
    }
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        const auto& [option, path] = outputs[i];
        if (auto refused = files::refusedOutput(option, path, guarded)) {
            return QString::fromStdString(*refused);
        }
        if (auto why = files::unwritableOutput(path)) {
            return QString::fromStdString(files::describeUnwritable(option, path, *why));
        }
        for (std::size_t j = 0; j < i; ++j) {
            if (files::outputOverGuarded(path, {{"", outputs[j].second, false}}) ||
                std::filesystem::weakly_canonical(std::filesystem::absolute(path)) ==
                    std::filesystem::weakly_canonical(std::filesystem::absolute(outputs[j].second))) {
                return QString::fromStdString(option + " " + path + " is also the " + outputs[j].first +
                                              " file: refused, nothing was written");
            }
        }
    }
    if (!o.screenshot.empty() && !screenshotFormat(o.screenshot)) {
        return QString::fromStdString("--screenshot " + o.screenshot + ": ." +
                                      std::filesystem::path(o.screenshot).extension().string().substr(1) +
                                      " is not an image format (" + imageSuffixes().toStdString() +
                                      "): refused, nothing was written");
    }
    return std::nullopt;
}

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
    ui::PanelMeter meter(window.findChild<QWidget*>(QStringLiteral("droMachine0")), startNs);
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
    QApplication app(argc, argv); // takes Qt's own options (-platform ...) out of argv first
    QApplication::setApplicationName(QStringLiteral("m350-studio"));
    ui::Language language(app);
    auto parsed = hmi::parseHmiCommandLine(argc, argv);
    if (!parsed.options) {
        return parsed.exitStatus;
    }
    const hmi::HmiOptions& o = *parsed.options;
    QString languageError;
    if (!language.set(QString::fromStdString(o.language), &languageError)) {
        return fail(languageError);
    }
    if (o.language == "zh_CN" && !language.fontProblem().isEmpty()) {
        std::fprintf(stderr, "%s\n", qPrintable(language.fontProblem()));
    }
    // The panel writes into its machine folder (MDI lines ...): the bundled machine is never
    // written; a replay or screenshot works on a throwaway copy, the desktop on the user's own.
    QTemporaryDir scratch;
    QString folder = QString::fromStdString(o.configDir);
    if (folder.isEmpty()) {
        QString error;
        auto copy = o.headlessRun() ? ui::copyBundledMachine(scratch.path(), &error) : ui::userMachineFolder(&error);
        if (!copy) {
            return fail(error);
        }
        folder = *copy;
    }
    if (auto refused = refusedOutput(o, folder)) {
        return fail(*refused);
    }
    auto loaded = config::loadMachineFolder(folder.toStdString());
    if (auto* error = std::get_if<config::ConfigError>(&loaded)) {
        return fail(QString::fromStdString(error->where() + ": " + error->message));
    }
    ui::MachineSession::Options sessionOptions;
    sessionOptions.clock = o.headlessRun() ? ui::MachineSession::Clock::Manual : ui::MachineSession::Clock::RealTime;
    sessionOptions.rate = o.rate;
    sessionOptions.homed = !o.unhomed;
    sessionOptions.tool = o.tool;
    sessionOptions.externalOutputLimit = o.dprntLimit;
    try {
        for (const std::string& broken : o.breaks) {
            sessionOptions.toolBreaks.push_back(sim::parseToolBreak(broken));
        }
    } catch (const CLI::ValidationError& e) {
        return fail(QString::fromStdString(e.what()), 64);
    }
    ui::MachineSession session(std::move(std::get<config::MachineConfig>(loaded)), sessionOptions);
    ui::MainWindow window(session, folder, &language);
    if (QFile style(QStringLiteral(":/panel/panel.qss")); style.open(QIODevice::ReadOnly)) {
        app.setStyleSheet(QString::fromUtf8(style.readAll()));
    }
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
            return fail(QStringLiteral("--record: %1").arg(error));
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
            return fail(QStringLiteral("--record: %1").arg(error));
        }
        if (switchTo.isEmpty()) {
            return status;
        }
        const QStringList args{QStringLiteral("--config"), switchTo, QStringLiteral("--lang"), language.current()};
        return QProcess::startDetached(QCoreApplication::applicationFilePath(), args)
                   ? 0
                   : fail(QStringLiteral("cannot start the panel again on %1").arg(switchTo));
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
            return fail(error);
        }
        if (error = ui::playReplay(window, session, *actions, replay, places); !error.isEmpty()) {
            return fail(error);
        }
    }
    ui::settle(session);
    if (!o.record.empty()) {
        if (QString error = window.stopRecording(); !error.isEmpty()) {
            return fail(QStringLiteral("--record: %1").arg(error));
        }
    }
    if (!o.screenshot.empty()) {
        QByteArray png;
        QBuffer buffer(&png);
        buffer.open(QIODevice::WriteOnly);
        if (!window.grab().save(&buffer, screenshotFormat(o.screenshot)->constData())) {
            return fail(QStringLiteral("--screenshot %1: the image could not be made").arg(QString::fromStdString(o.screenshot)));
        }
        if (auto error = writeOutput(o.screenshot, png)) {
            return fail(QStringLiteral("--screenshot: %1").arg(*error));
        }
    }
    if (!o.state.empty()) {
        if (auto error = writeOutput(o.state, QJsonDocument(window.state()).toJson(QJsonDocument::Indented))) {
            return fail(QStringLiteral("--state: %1").arg(*error));
        }
    }
    return 0;
}
