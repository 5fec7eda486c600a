#include "ui/panel/MainWindow.h"

#include "core/files/OutputGuard.h"
#include "ui/actions/ActionRecorder.h"
#include "ui/actions/KeyboardMap.h"
#include "ui/i18n/AlarmText.h"
#include "ui/i18n/Language.h"
#include "ui/pages/Page.h"
#include "ui/pages/PageId.h"
#include "ui/pages/PageTable.h"
#include "ui/pages/ProgramPage.h"
#include "ui/panel/BackupImportFlow.h"
#include "ui/panel/HandwheelWidget.h"
#include "ui/panel/KeyPad.h"
#include "ui/panel/MachineQuestions.h"
#include "ui/panel/PageStack.h"
#include "ui/panel/PanelBody.h"
#include "ui/panel/PanelMode.h"
#include "ui/panel/PanelStateJson.h"
#include "ui/panel/PromptBox.h"
#include "ui/panel/SoftkeyBar.h"
#include "ui/panel/StatusLine.h"
#include "ui/widgets/MeasuredLabel.h"
#include "ui/widgets/WrappedLabel.h"

#include <QApplication>
#include <QEvent>
#include <QFileDialog>
#include <QJsonArray>
#include <QKeyEvent>
#include <QLabel>
#include <QMenuBar>
#include <QStackedWidget>
#include <QVBoxLayout>

namespace m350::ui {

MainWindow::MainWindow(MachineSession& session, QString machineFolder, Language* language, QWidget* parent)
    : QMainWindow(parent), session_(session), context_(session, std::move(machineFolder)), language_(language) {
    setObjectName("panel");
    auto* screen = new QWidget(this);
    screen->setObjectName("screen");
    auto* column = new QVBoxLayout(screen);
    column->setContentsMargins(0, 0, 0, 0);
    column->setSpacing(2);
    status_ = new StatusLine(screen);
    stack_ = new PageStack(screen);
    message_ = new MeasuredLabel(screen);
    message_->setObjectName("messageLine");
    alarm_ = new WrappedLabel(screen);
    alarm_->setObjectName("alarmLine");
    alarm_->hide();
    softkeys_ = new SoftkeyBar(screen);
    column->addWidget(status_);
    column->addWidget(stack_, 1);
    column->addWidget(message_);
    column->addWidget(alarm_);
    column->addWidget(softkeys_);
    dispatcher_ = new ActionDispatcher(*this, session_, this);
    keys_ = new KeyPad([this](const OperatorAction& a) { dispatcher_->dispatch(a); }, this);
    keys_->setFixedWidth(348);
    setCentralWidget(new PanelBody(screen, keys_, this));
    prompt_ = new PromptBox(this);
    questions_ = std::make_unique<MachineQuestions>(session_, context_, *prompt_);
    context_.attach(prompt_, [this](const QString& text) { notify(text); });
    recorder_ = new ActionRecorder([this] { return snapshot_ ? snapshot_->sessionTime : 0.0; }, this);
    connect(dispatcher_, &ActionDispatcher::dispatched, recorder_, &ActionRecorder::record);
    connect(recorder_, &ActionRecorder::failed, this,
            [this](const QString& why) { notify(tr("Recording stopped: %1").arg(why)); });
    connect(softkeys_, &SoftkeyBar::pressed, this,
            [this](int number) { dispatcher_->dispatch(OperatorAction::softkeyPress(number)); });
    addPages();
    buildMenu();
    connect(&session_, &MachineSession::snapshotReady, this, &MainWindow::onSnapshot);
    qApp->installEventFilter(this);
    resize(1024, 600);
    showPage(PageId::monitor);
    retranslate();
}

MainWindow::~MainWindow() { qApp->removeEventFilter(this); }

void MainWindow::addPages() {
    for (const PageTable::Entry& entry : PageTable::entries()) {
        addPage(entry.make(context_, stack_));
    }

}

void MainWindow::addPage(Page* page) {
    pages_.insert(page->id(), page);
    stack_->addWidget(page);
    connect(page, &Page::navigate, this, [this](const QString& id) { showPage(id); });
    connect(page, &Page::editSource, this, [this](const QString& file, int line) {
        if (auto* program = qobject_cast<ProgramPage*>(pages_.value(PageId::program)); program && showPage(PageId::program)) {
            program->editAt(file, line);
            refreshSoftkeys();
        }
    });
    connect(page, &Page::softkeysChanged, this, [this, page] {
        if (page == currentPage()) {
            refreshSoftkeys();
        }
    });
}

bool MainWindow::showPage(const QString& id) {
    Page* page = pages_.value(id);
    if (!page) {
        return false; // every id of PageTable has its page: only a caller's typo lands here
    }
    current_ = page;
    if (page->drawsMachine() != sceneWatched_) {
        sceneWatched_ = page->drawsMachine();
        session_.watchScene(sceneWatched_);
    }
    if (!holdRendering_ || page->readsLayout()) {
        stack_->setCurrentWidget(page);
    }
    refreshSoftkeys();
    page->opened();
    if (snapshot_) {
        renderHeld_ = true;
        statusHeld_ = true;
        if (!holdRendering_ || page->rendersEverySnapshot()) {
            renderHeld();
        }
    }
    return true;
}

void MainWindow::holdRendering(bool hold) {
    holdRendering_ = hold;
    if (!hold) {
        showHeldPage();
        renderHeld();
        if (softkeysHeld_) {
            refreshSoftkeys();
        }
    }
}

void MainWindow::showHeldPage() { stack_->setCurrentWidget(current_); }

void MainWindow::renderHeld() {
    if ((renderHeld_ || statusHeld_) && snapshot_) {
        status_->render(*snapshot_, currentPage()->id(), currentPage()->title());
    }
    if (renderHeld_ && snapshot_) {
        currentPage()->render(*snapshot_);
    }
    renderHeld_ = false;
    statusHeld_ = false;
}

Page* MainWindow::currentPage() const { return current_; }

void MainWindow::refreshSoftkeys() {
    softkeysHeld_ = holdRendering_; // nothing reads the bar's buttons: a softkey asks the page
    if (!softkeysHeld_) {
        softkeys_->show(currentPage()->softkeys());
    }
}

void MainWindow::pressSoftkey(int number) {
    QVector<Page::Softkey> keys = currentPage()->softkeys();
    if (number < 1 || number > keys.size() || keys[number - 1].text.isEmpty()) {
        return;
    }
    if (!keys[number - 1].enabled) {
        // a key with a reason says it; one greyed out for what is not there yet does nothing
        if (!keys[number - 1].tooltip.isEmpty()) {
            notify(keys[number - 1].tooltip);
        }
        return;
    }
    notice_.clear();
    currentPage()->softkey(number);
}

void MainWindow::setLanguage(const QString& language) {
    QString error;
    if (language_ && !language_->set(language, &error)) {
        notify(error);
    }
}

void MainWindow::askJogStep() {
    context_.askText(tr("Input the step distance (mm):"), {}, [this](std::optional<QString> text) {
        bool ok = false;
        double step = text ? text->toDouble(&ok) : 0.0;
        if (text && (!ok || step <= 0.0 || step > 100.0)) {
            notify(tr("Step distance must be a number from 0.001 to 100"));
        } else if (text) {
            session_.setJogStep(step);
        }
    });
}

void MainWindow::switchWheel(int axis, int step) { keys_->handwheel()->select(axis, step); }

void MainWindow::notify(const QString& text) {
    notice_ = text;
    message_->setText(text);
}

QString MainWindow::messageText() const { return message_->text(); }

void MainWindow::setStandingNote(const QString& text) {
    if (message_->text() == standingNote_) {
        message_->setText(text);
    }
    standingNote_ = text;
}
QString MainWindow::alarmText() const { return alarm_->text(); }

void MainWindow::onSnapshot(const SnapshotPtr& snapshot) {
    snapshot_ = snapshot;
    const PanelSnapshot& s = *snapshot;
    if (holdRendering_ && !currentPage()->rendersEverySnapshot()) {
        renderHeld_ = true;
    } else if (holdRendering_) {
        // the page keeps something of every snapshot; the status line shows the latest alone
        statusHeld_ = true;
        currentPage()->render(s);
        renderHeld_ = false;
    } else {
        status_->render(s, currentPage()->id(), currentPage()->title());
        currentPage()->render(s);
        renderHeld_ = false;
    }
    keys_->render(s); // the handwheel's axis follows the machine's axes: a wheel click reads it
    QString message = s.status.notice ? AlarmText::message(*s.status.notice) : QString::fromStdString(s.status.message);
    if (s.status.run == controller::PanelStatus::Run::Hold) {
        QString why = QString::fromStdString(s.status.programStop);
        message = tr("Pause", "msg 114") + (why.isEmpty() ? QString() : QStringLiteral(": ") + why);
    }
    if (!s.lastError.isEmpty()) {
        message = s.lastError;
    }
    message_->setText(!message.isEmpty() ? message : !notice_.isEmpty() ? notice_ : standingNote_);
    QString alarm;
    if (s.status.alarm) {
        alarm = AlarmText::located(*s.status.alarm);
    } else if (s.status.sensorWait) {
        const auto& w = *s.status.sensorWait;
        alarm = tr("Waiting for %1 = %2 for %3 s (%4:%5)")
                    .arg(QString::fromStdString(w.input))
                    .arg(w.awaitedLevel)
                    .arg(w.seconds, 0, 'f', 1)
                    .arg(QString::fromStdString(w.file))
                    .arg(w.line);
    }
    alarm_->setText(alarm);
    alarm_->setVisible(!alarm.isEmpty());
    questions_->ask(s);
}

QJsonObject MainWindow::state() const {
    QJsonObject out = snapshot_ ? panelStateJson(*snapshot_) : QJsonObject{};
    out["page"] = currentPage()->id();
    if (snapshot_) {
        out["mode"] = PanelText::modeKey(displayedMode(*snapshot_, currentPage()->id()));
    }
    out["message"] = messageText();
    out["alarm_text"] = alarmText();
    out["language"] = language_ ? language_->current() : QString();
    out["prompt"] = prompt_->active() ? prompt_->question() : QString();
    QJsonArray softkeys;
    for (int number = 1; number <= currentPage()->softkeys().size(); ++number) {
        softkeys.append(softkeys_->label(number));
    }
    out["softkeys"] = softkeys;
    for (Page* page : pages_) {
        QJsonObject extra = page->state();
        for (auto it = extra.begin(); it != extra.end(); ++it) {
            out[it.key()] = it.value();
        }
    }
    return out;
}

bool MainWindow::eventFilter(QObject* watched, QEvent* event) {
    const bool press = event->type() == QEvent::KeyPress;
    if (!press && event->type() != QEvent::KeyRelease) {
        return QMainWindow::eventFilter(watched, event);
    }
    QWidget* active = QApplication::activeWindow();
    // window(): the panel may sit inside another (训练 Training's); hidden, it takes no keys
    if ((active != window() && active != prompt_) || !isVisible()) {
        return false;
    }
    auto action = actionForKey(*static_cast<QKeyEvent*>(event), press);
    if (!action) {
        return false;
    }
    if (action->kind == OperatorAction::Kind::Wheel) {
        keys_->handwheel()->turn(action->wheel.detents);
    } else {
        dispatcher_->dispatch(*action);
    }
    return true;
}

void MainWindow::buildMenu() {
    panelMenu_ = menuBar()->addMenu(QString());
    panelMenu_->addAction(QStringLiteral("中文"), this, [this] { setLanguage(QStringLiteral("zh_CN")); });
    panelMenu_->addAction(QStringLiteral("English"), this, [this] { setLanguage(QStringLiteral("en")); });
    panelMenu_->addSeparator();
    QAction* record = panelMenu_->addAction(QString(), this, [this] {
        if (recorder_->recording()) {
            const QString error = recorder_->stop();
            notify(error.isEmpty() ? tr("Recording stopped") : error);
            return;
        }
        QString path = QFileDialog::getSaveFileName(this, tr("Record operator actions"), {}, "JSON Lines (*.jsonl)");
        QString error;
        if (!path.isEmpty() && !recorder_->start(path, &error)) {
            notify(error);
        }
    });
    record->setObjectName("recordAction");
    QAction* retrace = panelMenu_->addAction(QString());
    retrace->setObjectName("retraceAction");
    retrace->setCheckable(true);
    retrace->setChecked(true);
    connect(retrace, &QAction::toggled, this, [this](bool on) { session_.setGuideRetrace(on); });
    panelMenu_->addSeparator();
    backupImport_ = new BackupImportFlow(context_, this);
    panelMenu_->addAction(QString(), backupImport_, &BackupImportFlow::start)->setObjectName("importBackupAction");
}

bool MainWindow::startRecording(const QString& path, QString* error) {
    // the recording never lands on what the panel reads or owns (Nothing lost, issue 26)
    std::vector<files::GuardedPath> guarded{{"the machine folder", context_.machineFolder().toStdString(), true}};
    if (snapshot_ && !snapshot_->programFile.isEmpty()) {
        guarded.push_back({"the loaded program", snapshot_->programFile.toStdString(), false});
    }
    if (auto hit = files::outputOverGuarded(path.toStdString(), guarded)) {
        *error = hit->inside ? tr("%1 is inside the machine folder %2: refused, nothing was written")
                                   .arg(path, context_.machineFolder())
                             : tr("%1 is the loaded program: refused, nothing was written").arg(path);
        return false;
    }
    if (auto why = files::unwritableOutput(path.toStdString())) {
        *error = unwritableText(path, *why);
        return false;
    }
    return recorder_->start(path, error);
}

QString MainWindow::stopRecording() { return recorder_->stop(); }

bool MainWindow::recording() const { return recorder_->recording(); }

QString MainWindow::unwritableText(const QString& path, files::Unwritable why) {
    switch (why) {
    case files::Unwritable::Folder: return tr("%1 is a folder, not a file: refused, nothing was written").arg(path);
    case files::Unwritable::Socket: return tr("%1 is a socket, not a file: refused, nothing was written").arg(path);
    case files::Unwritable::BlockDevice:
        return tr("%1 is a disk (block device), not a file: refused, nothing was written").arg(path);
    case files::Unwritable::NoFolder:
    case files::Unwritable::ParentNotFolder:
        return tr("%1: its folder does not exist or is not a folder: refused, nothing was written").arg(path);
    }
    return path;
}

void MainWindow::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
    }
    QMainWindow::changeEvent(event);
}

void MainWindow::retranslate() {
    setWindowTitle(tr("M350 Studio"));
    panelMenu_->setTitle(tr("Panel"));
    for (QAction* action : panelMenu_->actions()) {
        if (action->objectName() == QLatin1String("recordAction")) {
            action->setText(tr("Record operator actions..."));
        } else if (action->objectName() == QLatin1String("retraceAction")) {
            action->setText(tr("MPG RUN: reverse wheel retraces the path"));
        } else if (action->objectName() == QLatin1String("importBackupAction")) {
            action->setText(tr("Import controller backup..."));
        }
    }
    refreshSoftkeys();
    if (snapshot_) {
        onSnapshot(snapshot_);
    }
}

} // namespace m350::ui
