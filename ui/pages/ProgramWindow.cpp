#include "ui/pages/ProgramWindow.h"

#include "ui/program/SourceFile.h"
#include "ui/widgets/MeasuredLabel.h"

#include <QDir>
#include <QFileInfo>
#include <QGridLayout>
#include <QLabel>
#include <QStyle>
#include <QVBoxLayout>

#include <algorithm>

namespace m350::ui {

namespace {

constexpr auto kMdiName = "MDI"; // what a run of MDI lines names its file (controller::loadMdi)

// Long lines are cut at the window's edge, never widen the Monitor.
QLabel* rowLabel(QWidget* parent, const char* name) {
    auto* label = new MeasuredLabel(parent);
    label->setObjectName(QLatin1String(name));
    label->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    label->setTextFormat(Qt::PlainText);
    return label;
}

} // namespace

ProgramWindow::ProgramWindow(QString machineFolder, QWidget* parent)
    : QFrame(parent), machineFolder_(std::move(machineFolder)) {
    setObjectName("programWindow");
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(4, 2, 4, 2);
    column->setSpacing(1);
    caption_ = rowLabel(this, "programWindowCaption");
    column->addWidget(caption_);
    auto* rows = new QGridLayout;
    rows->setHorizontalSpacing(0); // the highlight runs unbroken from the number to the text
    rows->setVerticalSpacing(0);
    for (int row = 0; row < kMostRows; ++row) {
        numbers_[static_cast<std::size_t>(row)] = rowLabel(this, "programLineNumber");
        numbers_[static_cast<std::size_t>(row)]->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
        numbers_[static_cast<std::size_t>(row)]->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Preferred);
        numbers_[static_cast<std::size_t>(row)]->setMinimumWidth(
            numbers_[static_cast<std::size_t>(row)]->fontMetrics().horizontalAdvance(QStringLiteral("00000  ")));
        texts_[static_cast<std::size_t>(row)] = rowLabel(this, "programLine");
        rows->addWidget(numbers_[static_cast<std::size_t>(row)], row, 0);
        rows->addWidget(texts_[static_cast<std::size_t>(row)], row, 1);
    }
    rows->setColumnStretch(1, 1);
    rows->setRowStretch(kMostRows, 1); // the rows stay together at the top
    column->addLayout(rows, 1);
    // the rows past kRows ask for no room (a window that showed them can still shrink: 1024x600
    // to 800x480): the layout does not set this widget's minimum, minimumSizeHint says kRows;
    // fitRows shows those the height holds
    column->setSizeConstraint(QLayout::SetNoConstraint);
    for (int row = kRows; row < kMostRows; ++row) {
        numbers_[static_cast<std::size_t>(row)]->hide();
        texts_[static_cast<std::size_t>(row)]->hide();
    }
    retranslate();
}

// The layout's width, the height of kRows rows (what the Monitor must give it at 800x480).
QSize ProgramWindow::minimumSizeHint() const {
    const QMargins margins = contentsMargins() + layout()->contentsMargins();
    const int height = caption_->sizeHint().height() + kRows * texts_[0]->sizeHint().height() + 6;
    return QSize(QFrame::minimumSizeHint().width(), height + margins.top() + margins.bottom());
}

QSize ProgramWindow::sizeHint() const { return minimumSizeHint(); }

void ProgramWindow::resizeEvent(QResizeEvent* event) {
    QFrame::resizeEvent(event);
    fitRows();
}

// As many rows as the height holds; a change shows the running block in the middle again.
void ProgramWindow::fitRows() {
    const int rowHeight = std::max(1, texts_[0]->sizeHint().height());
    const int room = contentsRect().height() - caption_->sizeHint().height() - 6;
    const int fit = std::clamp(room / rowHeight, kRows, kMostRows);
    if (fit == rows_) {
        return;
    }
    rows_ = fit;
    for (int row = 0; row < kMostRows; ++row) {
        numbers_[static_cast<std::size_t>(row)]->setVisible(row < rows_);
        texts_[static_cast<std::size_t>(row)]->setVisible(row < rows_);
    }
    redraw();
}

void ProgramWindow::render(const PanelSnapshot& snapshot) {
    const controller::PanelStatus& s = snapshot.status;
    // a run that stopped on an alarm or the E-stop keeps its block shown; a finished one does not
    using Run = controller::PanelStatus::Run;
    const bool inRun = s.line > 0 && !s.file.empty() && s.run != Run::Idle && s.run != Run::Finished;
    QString name;
    if (inRun) {
        name = QString::fromStdString(s.file);
    } else if (!snapshot.programFile.isEmpty()) {
        name = QFileInfo(snapshot.programFile).fileName();
    }
    const int running = inRun ? static_cast<int>(s.line) : 0;
    const bool sameMdi = name != QLatin1String(kMdiName) || mdi_ == snapshot.mdiLines;
    if (name == name_ && running == running_ && sameMdi) {
        return; // the same block as the last frame: nothing to redraw
    }
    if (name != name_ || !sameMdi) {
        use(name, snapshot);
    }
    name_ = name;
    running_ = running;
    redraw();
}

// Finds the text of the file the run names: the MDI lines, the loaded program, or a file of the
// machine folder (the macro libraries, the hook files, mdi.nc).
void ProgramWindow::use(const QString& name, const PanelSnapshot& snapshot) {
    source_ = Source{};
    mdi_.reset();
    if (name.isEmpty()) {
        return;
    }
    if (name == QLatin1String(kMdiName) && snapshot.mdiLines) {
        mdi_ = snapshot.mdiLines;
        source_.key = name;
        source_.lines = *mdi_;
        return;
    }
    QString path = QFileInfo(snapshot.programFile).fileName() == name ? snapshot.programFile
                                                                      : QDir(machineFolder_).filePath(name);
    const QFileInfo info(path);
    auto known = read_.constFind(path);
    if (known != read_.constEnd() && known->modified == info.lastModified() && known->size == info.size()) {
        source_ = *known;
        return;
    }
    source_.key = path;
    source_.modified = info.lastModified();
    source_.size = info.size();
    QString error;
    if (auto file = SourceFile::read(path, &error)) {
        source_.lines = file->text.split(QLatin1Char('\n'));
        read_.insert(path, source_);
    } else {
        source_.unreadable = true; // gone or unreadable: the caption says so, the rows stay empty
    }
}

void ProgramWindow::redraw() {
    const int count = static_cast<int>(source_.lines.size());
    if (running_ > 0) {
        first_ = std::clamp(running_ - rows_ / 2, 1, std::max(1, count - rows_ + 1));
    } else {
        first_ = count > 0 ? 1 : 0;
    }
    for (int row = 0; row < rows_; ++row) {
        const auto index = static_cast<std::size_t>(row);
        const int line = first_ + row;
        const bool shown = first_ > 0 && line <= count;
        numbers_[index]->setText(shown ? QString::number(line) : QString());
        texts_[index]->setText(shown ? source_.lines[line - 1] : QString());
        const bool highlighted = shown && line == running_;
        if (texts_[index]->property("running").toBool() != highlighted) {
            for (QLabel* label : {numbers_[index], texts_[index]}) {
                label->setProperty("running", highlighted);
                label->style()->unpolish(label);
                label->style()->polish(label);
            }
        }
    }
    retranslate();
}

void ProgramWindow::retranslate() {
    if (name_.isEmpty()) {
        caption_->setText(tr("No program loaded"));
    } else if (source_.unreadable) {
        caption_->setText(tr("%1: cannot be read").arg(name_));
    } else if (running_ > 0) {
        caption_->setText(tr("%1   Line %2").arg(name_).arg(running_));
    } else {
        caption_->setText(name_);
    }
}

QString ProgramWindow::runningText() const {
    for (int row = 0; row < rows_; ++row) {
        if (rowHighlighted(row)) {
            return texts_[static_cast<std::size_t>(row)]->text();
        }
    }
    return {};
}

QString ProgramWindow::captionText() const { return caption_->text(); }

QString ProgramWindow::rowText(int row) const {
    const auto index = static_cast<std::size_t>(row);
    return numbers_[index]->text() + QStringLiteral("  ") + texts_[index]->text();
}

bool ProgramWindow::rowHighlighted(int row) const {
    return texts_[static_cast<std::size_t>(row)]->property("running").toBool();
}

} // namespace m350::ui
