#include "ui/pages/ProgramPage.h"

#include "ui/pages/PanelContext.h"
#include "core/config/CallCodeParameters.h"
#include "core/params/ParameterNumbers.h"
#include "ui/program/CodeView.h"
#include "ui/program/ProgramEditor.h"
#include "ui/program/ProgramList.h"
#include "ui/program/SimulationPanel.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QVBoxLayout>

#include <variant>

namespace m350::ui {

namespace {

config::MachineConfig machineOf(const QString& folder) {
    auto loaded = config::loadMachineFolder(folder.toStdString());
    auto* machine = std::get_if<config::MachineConfig>(&loaded);
    return machine ? std::move(*machine) : config::MachineConfig{};
}

QString modeName(ProgramPage::Mode mode) {
    switch (mode) {
    case ProgramPage::Mode::List: return QStringLiteral("list");
    case ProgramPage::Mode::Editor: return QStringLiteral("editor");
    case ProgramPage::Mode::Simulation: return QStringLiteral("simulation");
    }
    return {};
}

} // namespace

ProgramPage::ProgramPage(PanelContext& context, QWidget* parent)
    : Page(context, parent), machine_(machineOf(context.machineFolder())), parsing_(config::parsingDialect(machine_)),
      userFolder_(QDir::homePath()) {
    setObjectName("programPage");
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(4, 4, 4, 4);
    stack_ = new QStackedWidget(this);
    list_ = new ProgramList(stack_);
    editor_ = new ProgramEditor(parsing_, machine_.libraries, stack_);
    simulation_ = new SimulationPanel(*machine_.dialect, stack_);
    stack_->addWidget(list_);
    stack_->addWidget(editor_);
    stack_->addWidget(simulation_);
    column->addWidget(stack_);
    QString error;
    localFolder_ = ProgramFiles::localFolder(context.machineFolder(), &error);
    if (!error.isEmpty()) {
        context.notify(error);
    }
    showDisk(ProgramFiles::Disk::Local);
}

QString ProgramPage::title() const { return tr("Program", "msg 301"); }

void ProgramPage::setUserFolder(const QString& folder) {
    userFolder_ = folder;
    if (list_->disk() == ProgramFiles::Disk::User) {
        showDisk(ProgramFiles::Disk::User);
    }
}

QString ProgramPage::folderOf(ProgramFiles::Disk disk) const {
    switch (disk) {
    case ProgramFiles::Disk::Local: return localFolder_;
    case ProgramFiles::Disk::User: return userFolder_;
    case ProgramFiles::Disk::System: return context().machineFolder();
    }
    return {};
}

ProgramFiles::Sort ProgramPage::sortOrder() const {
    int value = snapshot_ ? static_cast<int>(snapshot_->status.parameters.get(param::kFileSortOrder)) : 0;
    return value == 1 ? ProgramFiles::Sort::Suffix : value == 2 ? ProgramFiles::Sort::Date : ProgramFiles::Sort::Name;
}

void ProgramPage::showDisk(ProgramFiles::Disk disk) { list_->showFolder(disk, folderOf(disk), sortOrder()); }

void ProgramPage::setMode(Mode mode) {
    mode_ = mode;
    stack_->setCurrentIndex(static_cast<int>(mode));
    emit softkeysChanged();
}

QVector<Page::Softkey> ProgramPage::softkeys() const {
    switch (mode_) {
    case Mode::List: return listSoftkeys();
    case Mode::Editor: {
        const QString later = tr("Not in the simulator");
        return {{tr("Save Exit", "msg 336"), true, {}}, {tr("Find Line", "msg 337"), true, {}},
                {tr("Del Line", "msg 338"), true, {}},  {QString(), false, {}},
                {tr("CAM", "msg 340"), false, later},   {tr("Teaching", "msg 341"), false, later}};
    }
    case Mode::Simulation:
        return {{tr("Speed %1").arg(SimulationPanel::speedName(kSpeeds[0])), true, {}},
                {tr("Speed %1").arg(SimulationPanel::speedName(kSpeeds[1])), true, {}},
                {tr("Speed %1").arg(SimulationPanel::speedName(kSpeeds[2])), true, {}},
                {tr("Speed %1").arg(SimulationPanel::speedName(kSpeeds[3])), true, {}},
                {tr("Simulate", "msg 332"), true, {}},
                {tr("Esc", "msg 939"), true, {}}};
    }
    return {};
}

QVector<Page::Softkey> ProgramPage::listSoftkeys() const {
    const bool system = list_->disk() == ProgramFiles::Disk::System;
    const QString libraries = tr("The macro libraries are edited here, not deleted, renamed or run");
    const QString copyTo = list_->disk() == ProgramFiles::Disk::User ? tr("Copy To Local", "msg 958")
                                                                     : tr("Copy To U Disk", "msg 327");
    return {{tr("Switch disks", "msg 324"), true, {}}, {tr("Del", "msg 325"), !system, libraries},
            {tr("Rename", "msg 326"), !system, libraries}, {copyTo, true, {}},
            {tr("New", "msg 328"), !system, libraries},   {tr("Edit", "msg 329"), true, {}},
            {tr("Copy", "msg 330"), true, {}},            {tr("Paste", "msg 331"), !system, libraries},
            {tr("Simulate", "msg 332"), !system, libraries}, {tr("Load NC", "msg 333"), !system, libraries},
            {tr("Clear local", "msg 334"), list_->disk() == ProgramFiles::Disk::Local, {}},
            {tr("Sort", "msg 335"), true, {}}};
}

void ProgramPage::softkey(int number) {
    switch (mode_) {
    case Mode::List: listSoftkey(number); break;
    case Mode::Editor: editorSoftkey(number); break;
    case Mode::Simulation: simulationSoftkey(number); break;
    }
}

void ProgramPage::listSoftkey(int number) {
    using Disk = ProgramFiles::Disk;
    const QString path = list_->selectedPath();
    switch (number) {
    case 1: {
        Disk next = list_->disk() == Disk::Local ? Disk::User : list_->disk() == Disk::User ? Disk::System : Disk::Local;
        showDisk(next);
        emit softkeysChanged();
        break;
    }
    case 2: deleteFile(); break;
    case 3: renameFile(); break;
    case 4: copyToOtherDisk(); break;
    case 5: newFile(); break;
    case 6: openEditor(path); break;
    case 7:
        clipboard_ = path;
        break;
    case 8: pasteFile(); break;
    case 9: startSimulation(path); break;
    case 10:
        if (!path.isEmpty()) {
            context().session().loadProgram(path);
            context().notify(tr("Select file", "msg 110") + QStringLiteral(" ") + list_->selectedName());
        }
        break;
    case 11: clearLocal(); break;
    case 12: {
        int next = (static_cast<int>(sortOrder()) + 1) % 3;
        context().session().setParameter(param::kFileSortOrder, next);
        list_->showFolder(list_->disk(), list_->folder(), static_cast<ProgramFiles::Sort>(next));
        break;
    }
    default: break;
    }
}

void ProgramPage::openEditor(const QString& path) {
    if (path.isEmpty()) {
        return;
    }
    QString error;
    if (!editor_->open(path, &error)) {
        context().notify(error);
        return;
    }
    setMode(Mode::Editor);
    if (snapshot_) {
        render(*snapshot_);
    }
}

void ProgramPage::editAt(const QString& path, int line) {
    openEditor(path);
    if (mode_ == Mode::Editor && editor_->path() == path) {
        editor_->view()->goToLine(line);
    }
}

// Leaves the editor; a saved file the machine has loaded is loaded again, so START runs the new text.
void ProgramPage::closeEditor(bool save) {
    if (save) {
        QString error;
        if (!editor_->save(&error)) {
            context().notify(tr("File save failed!", "msg 907") + QStringLiteral(" ") + error);
            return;
        }
        const QString path = editor_->path();
        if (snapshot_ && QFileInfo(snapshot_->programFile) == QFileInfo(path) && !busyWith(path)) {
            context().session().loadProgram(path);
        }
    }
    setMode(Mode::List);
    list_->refresh();
    list_->select(QFileInfo(editor_->path()).fileName());
}

void ProgramPage::editorSoftkey(int number) {
    switch (number) {
    case 1: closeEditor(true); break;
    case 2: findLine(); break;
    case 3: editor_->deleteLine(); break;
    default: break;
    }
}

void ProgramPage::findLine() {
    context().askText(tr("Pls input searching line No:", "msg 894"), {}, [this](std::optional<QString> text) {
        bool ok = false;
        int line = text ? text->trimmed().toInt(&ok) : 0;
        if (ok && line > 0) {
            editor_->view()->goToLine(line);
        }
    });
}

void ProgramPage::startSimulation(const QString& path) {
    if (path.isEmpty()) {
        return;
    }
    QString error;
    auto file = SourceFile::read(path, &error);
    if (!file) {
        context().notify(error);
        return;
    }
    simulation_->open(path, file->text);
    context().session().startSimulation(path, speed_);
    setMode(Mode::Simulation);
}

void ProgramPage::simulationSoftkey(int number) {
    if (number >= 1 && number <= 4) {
        speed_ = kSpeeds[number - 1];
        context().session().setSimulationSpeed(speed_);
    } else if (number == 5) {
        startSimulation(snapshot_ ? snapshot_->simulation.file : QString());
    } else if (number == 6) {
        context().session().stopSimulation();
        setMode(Mode::List);
    }
}

bool ProgramPage::key(const QString& name) {
    switch (mode_) {
    case Mode::List:
        if (name == QLatin1String("UP") || name == QLatin1String("DOWN")) {
            list_->moveSelection(name == QLatin1String("UP") ? -1 : 1);
            return true;
        }
        if (name == QLatin1String("ENTER")) {
            openEditor(list_->selectedPath());
            return true;
        }
        return false;
    case Mode::Editor:
        if (name == QLatin1String("ESC")) {
            if (!editor_->modified()) {
                closeEditor(false);
                return true;
            }
            context().ask(tr("[Enter] to save,[Esc] is not to save.", "msg 893"),
                          [this](bool save) { closeEditor(save); });
            return true;
        }
        return editor_->key(name);
    case Mode::Simulation:
        if (name == QLatin1String("ESC")) {
            simulationSoftkey(6);
            return true;
        }
        return false;
    }
    return false;
}

bool ProgramPage::typed(const QString& text) {
    if (mode_ != Mode::Editor) {
        return false;
    }
    editor_->type(text);
    return true;
}

bool ProgramPage::busyWith(const QString& path) const {
    using Run = controller::PanelStatus::Run;
    const controller::PanelStatus& s = snapshot_->status;
    return (s.run == Run::Running || s.run == Run::Hold) && !s.mdi &&
           QFileInfo(snapshot_->programFile) == QFileInfo(path);
}

void ProgramPage::render(const PanelSnapshot& snapshot) {
    const bool sortChanged = !snapshot_ || snapshot_->status.parameters.get(param::kFileSortOrder) != snapshot.status.parameters.get(param::kFileSortOrder);
    snapshot_ = context().snapshot();
    if (!snapshot_ || &*snapshot_ != &snapshot) {
        snapshot_ = std::make_shared<const PanelSnapshot>(snapshot);
    }
    if (sortChanged && mode_ == Mode::List) {
        showDisk(list_->disk());
    }
    if (mode_ == Mode::Editor) {
        const bool running = busyWith(editor_->path()) &&
                             QString::fromStdString(snapshot.status.file) == QFileInfo(editor_->path()).fileName();
        editor_->showRunning(running ? static_cast<int>(snapshot.status.line) : 0);
    }
    if (mode_ == Mode::Simulation) {
        simulation_->render(snapshot);
    }
}

void ProgramPage::retranslate() {
    list_->retranslate();
    editor_->retranslate();
}

QJsonObject ProgramPage::state() const {
    QJsonObject out{{"program_mode", modeName(mode_)},
                     {"program_disk", list_->diskName(list_->disk())},
                     {"program_files", QJsonArray::fromStringList(list_->names())},
                     {"program_selected", list_->selectedName()}};
    if (mode_ == Mode::Editor) {
        QJsonArray marks;
        for (const CodeView::Mark& m : editor_->view()->marks()) {
            marks.append(QJsonObject{{"line", m.line}, {"column", m.column}, {"message", m.message}});
        }
        out["editor_file"] = QFileInfo(editor_->path()).fileName();
        out["editor_line"] = editor_->view()->currentLine();
        out["editor_running_line"] = editor_->view()->runningLine();
        out["editor_marks"] = marks;
        out["editor_modified"] = editor_->modified();
    }
    if (mode_ == Mode::Simulation) {
        out["simulation_line"] = simulation_->code()->runningLine();
        out["simulation_points"] = static_cast<double>(simulation_->points());
        out["simulation_info"] = simulation_->infoText();
    }
    return out;
}

} // namespace m350::ui
