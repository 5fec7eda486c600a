#include "ui/training/RunningProgramView.h"

#include "ui/program/CodeView.h"
#include "ui/program/SourceFile.h"
#include "ui/widgets/MeasuredLabel.h"

#include <QDir>
#include <QEvent>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QTextBlock>
#include <QTimer>
#include <QVBoxLayout>

namespace m350::ui {

namespace {

constexpr auto kRunningMdiName = "MDI"; // what a run of MDI lines names its file (controller::loadMdi)

} // namespace

RunningProgramView::RunningProgramView(const gcode::Dialect& dialect, QString machineFolder, QWidget* parent)
    : QWidget(parent), machineFolder_(std::move(machineFolder)) {
    setObjectName("reviewProgramView");
    setAttribute(Qt::WA_StyledBackground); // it lies over the panel: the style sheet's background hides it
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(4, 2, 4, 2);
    column->setSpacing(2);
    caption_ = new MeasuredLabel(this);
    caption_->setObjectName("reviewProgramCaption");
    caption_->setTextFormat(Qt::PlainText);
    machine_ = new MeasuredLabel(this);
    machine_->setObjectName("reviewProgramMachine");
    machine_->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    auto* top = new QHBoxLayout;
    top->addWidget(caption_, 1);
    top->addWidget(machine_);
    column->addLayout(top);
    code_ = new CodeView(dialect, this);
    code_->setReadOnly(true); // the view follows the running line (CodeView::setRunningLine)
    column->addWidget(code_, 1);
    retranslate();
}

void RunningProgramView::render(const PanelSnapshot& snapshot) {
    const controller::PanelStatus& s = snapshot.status;
    using Run = controller::PanelStatus::Run;
    // a run held, stopped on an alarm or the E-stop keeps its block shown; a finished one does not
    const bool inRun = s.line > 0 && !s.file.empty() && s.run != Run::Idle && s.run != Run::Finished;
    if (inRun) {
        show(QString::fromStdString(s.file), snapshot);
    }
    code_->setRunningLine(inRun && !unreadable_ ? static_cast<int>(s.line) : 0);
    machine_->setText(QStringLiteral("T%1   X %2  Y %3  Z %4")
                          .arg(s.tool)
                          .arg(s.machine[0], 0, 'f', 3)
                          .arg(s.machine[1], 0, 'f', 3)
                          .arg(s.machine[2], 0, 'f', 3));
    retranslate();
}

// Puts the named file's text in the view when it is another file than the one shown, or the same
// one changed on disk, or other MDI lines.
void RunningProgramView::show(const QString& name, const PanelSnapshot& snapshot) {
    if (name == QLatin1String(kRunningMdiName) && snapshot.mdiLines) {
        if (name == name_ && snapshot.mdiLines == mdi_) {
            return;
        }
        name_ = name;
        path_.clear();
        mdi_ = snapshot.mdiLines;
        unreadable_ = false;
        code_->setProgram(mdi_->join(QLatin1Char('\n')));
        return;
    }
    const QString path = QFileInfo(snapshot.programFile).fileName() == name ? snapshot.programFile
                                                                             : QDir(machineFolder_).filePath(name);
    const QFileInfo info(path);
    if (path == path_ && info.lastModified() == modified_ && info.size() == size_) {
        return;
    }
    name_ = name;
    path_ = path;
    mdi_.reset();
    modified_ = info.lastModified();
    size_ = info.size();
    QString error;
    std::optional<SourceFile> file = SourceFile::read(path, &error);
    unreadable_ = !file;
    code_->setProgram(file ? file->text : QString());
}

int RunningProgramView::runningLine() const { return code_->runningLine(); }

QString RunningProgramView::runningText() const {
    const int line = code_->runningLine();
    return line > 0 ? code_->document()->findBlockByNumber(line - 1).text() : QString();
}

QString RunningProgramView::captionText() const { return caption_->text(); }

void RunningProgramView::retranslate() {
    const int line = code_->runningLine();
    if (name_.isEmpty()) {
        caption_->setText(tr("No program has run yet"));
    } else if (unreadable_) {
        caption_->setText(tr("%1: cannot be read").arg(name_));
    } else if (line > 0) {
        caption_->setText(tr("%1   Line %2").arg(name_).arg(line));
    } else {
        caption_->setText(tr("%1   (not running)").arg(name_));
    }
}

// A line set while the view was hidden could not be brought to the middle: now it can, once the
// view has its size.
void RunningProgramView::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    QTimer::singleShot(0, code_, [code = code_] { code->centerCursor(); });
}

void RunningProgramView::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
    }
    QWidget::changeEvent(event);
}

} // namespace m350::ui
