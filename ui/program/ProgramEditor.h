#pragma once

#include "ui/program/CodeView.h"
#include "ui/program/SourceFile.h"

#include "core/config/MachineConfig.h"

#include <QWidget>

class QLabel;

namespace m350::ui {

class ProgramChecker;

// 编辑: one program open in its own encoding, coloured, checked by the parser as it is typed
// (CodeView marks, the first findings listed under it), saved atomically in that encoding.
class ProgramEditor : public QWidget {
    Q_OBJECT
public:
    ProgramEditor(const gcode::Dialect& dialect, std::vector<config::LibraryFile> libraries, QWidget* parent = nullptr);

    static constexpr qsizetype kCheckAtOnceChars = 256 * 1024;
    static constexpr qint64 kMaxBytes = 64LL * 1024 * 1024; // 文件过大,无法进行编辑操作! beyond
    bool open(const QString& path, QString* error);
    bool save(QString* error);
    const QString& path() const { return file_.path; }
    bool modified() const;
    SourceFile::Encoding encoding() const { return file_.encoding; }
    CodeView* view() const { return view_; }
    ProgramChecker* checker() const { return checker_; }

    // The panel's keys: ENTER a new line, BACKSPACE, the arrows; typed text goes in at the cursor.
    bool key(const QString& name);
    void type(const QString& text);
    void deleteLine();
    // The machine runs this file's line `line` (0: it does not); while it does the text is locked.
    void showRunning(int line);
    void retranslate();

private:
    void textEdited();
    void showMarks(const QVector<CodeView::Mark>& marks);
    CodeView* view_;
    QLabel* title_;
    QLabel* findings_;
    ProgramChecker* checker_;
    SourceFile file_;
    bool loading_ = false;
};

} // namespace m350::ui
