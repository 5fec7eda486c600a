#pragma once

#include "core/files/OutputGuard.h"

#include "ui/actions/ActionDispatcher.h"
#include "ui/actions/PanelScreen.h"
#include "ui/pages/PanelContext.h"
#include "ui/panel/PromptBox.h"
#include "ui/session/PanelSnapshot.h"

#include <QJsonObject>
#include <QMainWindow>
#include <QMap>

#include <memory>

class QLabel;

namespace m350::ui {

class BackupImportFlow;
class KeyPad;
class MachineQuestions;
class Language;
class Page;
class PageStack;
class SoftkeyBar;
class StatusLine;

// The panel: status line on top, the page in the middle, the message line and the softkeys under
// it, the panel's keys and the handwheel on the right where the window has room (PanelBody). It shows snapshots and hands every
// operator action to its dispatcher; it owns no machine state.
class MainWindow : public QMainWindow, public PanelScreen {
    Q_OBJECT
public:
    MainWindow(MachineSession& session, QString machineFolder, Language* language, QWidget* parent = nullptr);
    ~MainWindow() override;

    ActionDispatcher& dispatcher() { return *dispatcher_; }
    PanelContext& context() { return context_; }
    bool showPage(const QString& id) override;
    Page* currentPage() const override;
    Page* page(const QString& id) const { return pages_.value(id); }
    void pressSoftkey(int number) override;
    void setLanguage(const QString& language) override;
    void askJogStep() override;
    void switchWheel(int axis, int step) override;
    void notify(const QString& text);
    // --record and the Panel menu: refused over the loaded program, inside the machine folder, or
    // onto a folder; a device is written as one.
    bool startRecording(const QString& path, QString* error);
    QString stopRecording(); // empty when every action reached the file, else why not
    bool recording() const;
    class ActionRecorder& recorder() { return *recorder_; }
    // A text the message line shows while nothing else is said (a training attempt's task and the
    // time left).
    void setStandingNote(const QString& text);
    BackupImportFlow& backupImport() { return *backupImport_; } // the Panel menu's 导入控制器备份

    StatusLine* statusLine() const { return status_; }
    SoftkeyBar* softkeys() const { return softkeys_; }
    KeyPad* keyPad() const { return keys_; }
    PromptBox* prompt() const override { return prompt_; }
    QString messageText() const;
    QString alarmText() const;
    // The panel's state for --state: page, mode, state, positions, tool, message, alarm, IO, MDI lines.
    QJsonObject state() const;
    // A headless replay: the page and status line render a snapshot only when something is about
    // to read them (renderHeld), a page that keeps what each snapshot showed still renders them all.
    // A page switch makes the page the one keys reach and snapshots render (currentPage), but the
    // stack shows it (and lays it out) only when the hold ends, unless the page reads its layout;
    // the softkey bar shows the keys of the page then too.
    void holdRendering(bool hold);
    void renderHeld();
    // The stack shows the current page now, while held too (before an action on a page that reads
    // its layout).
    void showHeldPage();

protected:
    void changeEvent(QEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void addPages();
    void addPage(Page* page);
    void onSnapshot(const SnapshotPtr& snapshot);
    void refreshSoftkeys();
    void buildMenu();
    void retranslate();
    static QString unwritableText(const QString& path, files::Unwritable why);

    MachineSession& session_;
    PanelContext context_;
    Language* language_;
    ActionDispatcher* dispatcher_;
    StatusLine* status_;
    PageStack* stack_;
    Page* current_ = nullptr; // the page the operator is on; the stack shows it but while held
    bool sceneWatched_ = false; // snapshots carry the machine's scene (the current page draws it)
    QLabel* message_;
    QLabel* alarm_;
    SoftkeyBar* softkeys_;
    KeyPad* keys_;
    PromptBox* prompt_;
    std::unique_ptr<MachineQuestions> questions_; // what the machine asks through prompt_
    QMap<QString, Page*> pages_;
    SnapshotPtr snapshot_;
    QString notice_;
    QString standingNote_;
    bool holdRendering_ = false;
    bool renderHeld_ = false; // a snapshot the page and status line have not rendered
    bool statusHeld_ = false; // a snapshot the status line has not rendered (the page has)
    bool softkeysHeld_ = false; // the softkey bar does not show the current page's keys
    QMenu* panelMenu_ = nullptr;
    class ActionRecorder* recorder_ = nullptr;
    BackupImportFlow* backupImport_ = nullptr;
};

} // namespace m350::ui
