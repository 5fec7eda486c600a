#include "ui/pages/GraphicsPage.h"

#include "ui/i18n/AlarmText.h"
#include "ui/view/MachineView.h"

#include <QDir>
#include <QFileInfo>
#include <QVBoxLayout>

namespace m350::ui {

namespace {

constexpr double kZoomStep = 1.5;
constexpr double kPanStep = 60.0; // pixels an arrow key moves the view

} // namespace

GraphicsPage::GraphicsPage(PanelContext& context, QWidget* parent) : Page(context, parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    view_ = new MachineView(this);
    layout->addWidget(view_);
    connect(view_, &MachineView::moveClicked, this, [this](const QString& file, int line) {
        const QString path = sourcePath(file);
        if (!path.isEmpty() && line > 0) {
            emit editSource(path, line);
        }
    });
}

// A move's file as the controller names it (the loaded program's or a machine library's name) to
// the file the editor opens; empty when there is none.
QString GraphicsPage::sourcePath(const QString& name) const {
    auto snapshot = context().snapshot();
    if (snapshot && QFileInfo(snapshot->programFile).fileName() == QFileInfo(name).fileName()) {
        return snapshot->programFile;
    }
    const QFileInfo inFolder(QDir(context().machineFolder()).filePath(name));
    return inFolder.isFile() ? inFolder.absoluteFilePath() : QString();
}

QString GraphicsPage::title() const { return tr("Simulation", "msg 312"); }

QVector<Page::Softkey> GraphicsPage::softkeys() const {
    return {{tr("Top View"), true, {}},   {tr("Front View"), true, {}}, {tr("Fit"), true, {}},
            {tr("Zoom In"), true, {}},    {tr("Zoom Out"), true, {}},   {tr("Back"), true, {}}};
}

void GraphicsPage::softkey(int number) {
    switch (number) {
    case 1: view_->setPlane(ViewPlane::Top); break;
    case 2: view_->setPlane(ViewPlane::Front); break;
    case 3: view_->fitNext(); break;
    case 4: view_->zoomBy(kZoomStep); break;
    case 5: view_->zoomBy(1.0 / kZoomStep); break;
    case 6: emit navigate(PageId::monitor); break;
    default: break;
    }
}

bool GraphicsPage::key(const QString& name) {
    if (name == QLatin1String("ESC")) {
        emit navigate(PageId::monitor);
    } else if (name == QLatin1String("ENTER")) {
        view_->fit();
    } else if (name == QLatin1String("LEFT")) {
        view_->panBy(-kPanStep, 0.0);
    } else if (name == QLatin1String("RIGHT")) {
        view_->panBy(kPanStep, 0.0);
    } else if (name == QLatin1String("UP")) {
        view_->panBy(0.0, -kPanStep);
    } else if (name == QLatin1String("DOWN")) {
        view_->panBy(0.0, kPanStep);
    } else {
        return false;
    }
    return true;
}

MachineViewContent GraphicsPage::contentOf(const PanelSnapshot& snapshot) {
    using Run = controller::PanelStatus::Run;
    const controller::PanelStatus& s = snapshot.status;
    MachineViewContent content;
    content.preview = snapshot.programPreview;
    content.scene = snapshot.scene;
    content.nose = preview::ScenePoint{s.machine(0), s.machine(1), s.machine(2)};
    // the run of the loaded program, not an MDI line's, walks along its path
    if (!s.mdi && content.preview.preview && s.run != Run::Idle && s.runMoves > 0) {
        const bool under = s.run == Run::Running || s.run == Run::Hold;
        content.done = static_cast<std::size_t>(under ? s.runMoves - 1 : s.runMoves);
        if (under) {
            content.current = content.done;
        }
    }
    if (s.alarm) {
        content.alarm = AlarmText::message(*s.alarm);
        if (s.alarmPlace) {
            content.alarmAt = preview::ScenePoint{(*s.alarmPlace)(0), (*s.alarmPlace)(1), (*s.alarmPlace)(2)};
        }
    }
    return content;
}

void GraphicsPage::render(const PanelSnapshot& snapshot) { view_->setContent(contentOf(snapshot)); }

QJsonObject GraphicsPage::state() const { return {{"graphics", view_->state()}}; }

} // namespace m350::ui
