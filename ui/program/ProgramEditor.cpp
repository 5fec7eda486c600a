#include "ui/program/ProgramEditor.h"

#include "ui/program/GcodeHighlighter.h"
#include "ui/program/ProgramChecker.h"
#include "ui/widgets/MeasuredLabel.h"
#include "ui/widgets/WrappedLabel.h"

#include <QFileInfo>
#include <QLabel>
#include <QTextBlock>
#include <QVBoxLayout>

namespace m350::ui {

ProgramEditor::ProgramEditor(const gcode::Dialect& dialect, std::vector<config::LibraryFile> libraries,
                             QWidget* parent)
    : QWidget(parent) {
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(0, 0, 0, 0);
    title_ = new MeasuredLabel(this);
    title_->setObjectName("editorTitle");
    view_ = new CodeView(dialect, this);
    findings_ = new WrappedLabel(this);
    findings_->setObjectName("editorFindings");
    findings_->setStyleSheet(QStringLiteral("color: #ff8080;"));
    column->addWidget(title_);
    column->addWidget(view_, 1);
    column->addWidget(findings_);
    checker_ = new ProgramChecker(dialect, std::move(libraries), this);
    connect(checker_, &ProgramChecker::checked, this, &ProgramEditor::showMarks);
    connect(view_->document(), &QTextDocument::contentsChange, this, [this] {
        if (!view_->highlighter()->formatting() && !loading_) {
            textEdited();
        }
    });
}

bool ProgramEditor::open(const QString& path, QString* error) {
    if (QFileInfo(path).size() > kMaxBytes) {
        *error = tr("File is too large to edit", "msg 137");
        return false;
    }
    auto file = SourceFile::read(path, error);
    if (!file) {
        return false;
    }
    file_ = std::move(*file);
    view_->setReadOnly(false);
    loading_ = true;
    view_->setProgram(file_.text);
    loading_ = false;
    view_->document()->setModified(false);
    findings_->clear();
    retranslate();
    // a file of usual size shows its findings as it opens; a large one a moment later
    if (file_.text.size() < kCheckAtOnceChars) {
        showMarks(ProgramChecker::diagnose(checker_->dialect(), checker_->libraries(), file_.path, file_.text));
    } else {
        checker_->schedule(file_.path, file_.text);
    }
    return true;
}

bool ProgramEditor::modified() const { return view_->document()->isModified(); }

bool ProgramEditor::save(QString* error) {
    SourceFile out = file_;
    out.text = view_->toPlainText();
    if (!out.write(error)) {
        return false;
    }
    file_ = std::move(out);
    view_->document()->setModified(false);
    return true;
}

void ProgramEditor::retranslate() {
    const QString encoding = file_.encoding == SourceFile::Encoding::Gbk ? QStringLiteral("GBK") : QStringLiteral("UTF-8");
    title_->setText(QStringLiteral("%1 %2  (%3)").arg(tr("Current File:", "msg 953"), QFileInfo(file_.path).fileName(),
                                                     encoding));
}

void ProgramEditor::textEdited() { checker_->schedule(file_.path, view_->toPlainText()); }

void ProgramEditor::showMarks(const QVector<CodeView::Mark>& marks) {
    view_->setMarks(marks);
    QStringList lines;
    for (int i = 0; i < marks.size() && i < 3; ++i) {
        lines << QStringLiteral("%1:%2: %3").arg(marks[i].line).arg(marks[i].column).arg(marks[i].message);
    }
    if (marks.size() > 3) {
        lines << tr("... %1 more").arg(marks.size() - 3);
    }
    findings_->setText(lines.join('\n'));
}

bool ProgramEditor::key(const QString& name) {
    if (view_->isReadOnly()) {
        return false;
    }
    QTextCursor cursor = view_->textCursor();
    if (name == QLatin1String("ENTER")) {
        cursor.insertBlock();
    } else if (name == QLatin1String("BACKSPACE")) {
        cursor.deletePreviousChar();
    } else if (name == QLatin1String("UP") || name == QLatin1String("DOWN")) {
        cursor.movePosition(name == QLatin1String("UP") ? QTextCursor::Up : QTextCursor::Down);
    } else if (name == QLatin1String("LEFT") || name == QLatin1String("RIGHT")) {
        cursor.movePosition(name == QLatin1String("LEFT") ? QTextCursor::Left : QTextCursor::Right);
    } else {
        return false;
    }
    view_->setTextCursor(cursor);
    return true;
}

void ProgramEditor::type(const QString& text) {
    if (!view_->isReadOnly()) {
        view_->insertPlainText(text);
    }
}

void ProgramEditor::deleteLine() {
    if (view_->isReadOnly()) {
        return;
    }
    QTextCursor cursor = view_->textCursor();
    cursor.beginEditBlock();
    cursor.movePosition(QTextCursor::StartOfBlock);
    if (cursor.block().next().isValid()) {
        cursor.movePosition(QTextCursor::NextBlock, QTextCursor::KeepAnchor);
    } else {
        cursor.movePosition(QTextCursor::EndOfBlock, QTextCursor::KeepAnchor);
        if (cursor.block().previous().isValid()) { // the last line: take its line break too
            cursor.movePosition(QTextCursor::StartOfBlock);
            cursor.movePosition(QTextCursor::PreviousCharacter);
            cursor.movePosition(QTextCursor::End, QTextCursor::KeepAnchor);
        }
    }
    cursor.removeSelectedText();
    cursor.endEditBlock();
    view_->setTextCursor(cursor);
}

void ProgramEditor::showRunning(int line) {
    view_->setReadOnly(line > 0);
    view_->setRunningLine(line);
}

} // namespace m350::ui
