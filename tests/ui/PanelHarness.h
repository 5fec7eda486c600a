#pragma once

// A panel on a throwaway copy of the default machine, with a manual clock: tests press keys and
// softkeys, type and turn the wheel through the dispatcher (the operator's path), let virtual
// time pass, and read the widgets.

#include "core/config/MachineConfig.h"
#include "ui/actions/OperatorAction.h"
#include "ui/i18n/Language.h"
#include "ui/panel/MainWindow.h"
#include "ui/replay/Replay.h"
#include "ui/session/MachineFolderCopy.h"
#include "ui/session/MachineSession.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <memory>
#include <variant>

namespace m350::test {

// A file's text (empty when it cannot be read), and a file written whole.
inline QString fileText(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()) : QString();
}
inline void putFile(const QString& path, const QByteArray& text) {
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly | QIODevice::Truncate)) << path.toStdString();
    file.write(text);
}

// While it lives the panel speaks English (tests that read English words the panel says through
// its translator); zh_CN, the panel's language, again after.
struct EnglishPanel;

class PanelHarness {
public:
    explicit PanelHarness(ui::MachineSession::Options options = {}) {
        QString error;
        auto copy = ui::copyBundledMachine(dir_.path(), &error);
        EXPECT_TRUE(copy) << error.toStdString();
        open(copy.value_or(QString()), options);
    }
    // A panel on a folder an earlier harness used (a restart of the panel on the same machine).
    explicit PanelHarness(const QString& folder, ui::MachineSession::Options options = {}) { open(folder, options); }
    ~PanelHarness() {
        window_.reset();
        session_.reset();
    }

    static void setLanguage(ui::Language* language) { language_ = language; }
    static ui::Language* language() { return language_; }

    void act(const ui::OperatorAction& action) {
        window_->dispatcher().dispatch(action);
        ui::settle(*session_);
    }
    void key(const QString& name) { act(ui::OperatorAction::key(name)); }
    void softkey(int number) { act(ui::OperatorAction::softkeyPress(number)); }
    void type(const QString& text) { act(ui::OperatorAction::typed(text)); }
    void page(const QString& id) { act(ui::OperatorAction::page(id)); }
    // Lets virtual time pass in display frames, the window showing each snapshot.
    void advance(double seconds) {
        constexpr double kFrame = 1.0 / 60.0;
        while (seconds > 1e-9) {
            double step = std::min(kFrame, seconds);
            session_->advance(step);
            QCoreApplication::processEvents();
            seconds -= step;
        }
        ui::settle(*session_);
    }
    // Turns the wheel `detents` per frame for `seconds` (as a steady hand would).
    void turnWheel(int axis, int step, int detentsPerFrame, double seconds) {
        constexpr double kFrame = 1.0 / 60.0;
        for (double t = 0.0; t < seconds - 1e-9; t += kFrame) {
            window_->dispatcher().dispatch(ui::OperatorAction::wheelTurn(axis, step, detentsPerFrame, kFrame));
            session_->advance(kFrame);
            QCoreApplication::processEvents();
        }
        ui::settle(*session_);
    }

    // Writes a program beside the machine folder and loads it, as the Program page's NC读取 does.
    void loadProgram(const QString& name, const QByteArray& text) {
        QString path = QDir(dir_.path()).filePath(name);
        QFile file(path);
        ASSERT_TRUE(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
        file.write(text);
        file.close();
        session_->loadProgram(path);
        ui::settle(*session_);
    }

    ui::MainWindow& window() { return *window_; }
    ui::MachineSession& session() { return *session_; }
    const QString& folder() const { return folder_; }
    template <class PageType> PageType* page() {
        return dynamic_cast<PageType*>(window_->currentPage());
    }

private:
    void open(const QString& folder, ui::MachineSession::Options options) {
        folder_ = folder;
        auto loaded = config::loadMachineFolder(folder_.toStdString());
        ASSERT_TRUE(std::holds_alternative<config::MachineConfig>(loaded))
            << std::get<config::ConfigError>(loaded).file << ": " << std::get<config::ConfigError>(loaded).message;
        options.clock = ui::MachineSession::Clock::Manual;
        session_ = std::make_unique<ui::MachineSession>(std::get<config::MachineConfig>(std::move(loaded)), options);
        window_ = std::make_unique<ui::MainWindow>(*session_, folder_, language_);
        window_->show();
        ui::settle(*session_);
    }

    QTemporaryDir dir_;
    QString folder_;
    std::unique_ptr<ui::MachineSession> session_;
    std::unique_ptr<ui::MainWindow> window_;
    static inline ui::Language* language_ = nullptr;
};

struct EnglishPanel {
    EnglishPanel() {
        QString error;
        EXPECT_TRUE(PanelHarness::language()->set(QStringLiteral("en"), &error)) << error.toStdString();
    }
    ~EnglishPanel() {
        QString error;
        PanelHarness::language()->set(QStringLiteral("zh_CN"), &error);
    }
    EnglishPanel(const EnglishPanel&) = delete;
    EnglishPanel& operator=(const EnglishPanel&) = delete;
};

} // namespace m350::test
