#pragma once

#include <QPlainTextEdit>
#include <QVector>

namespace m350::gcode {
struct Dialect;
}

namespace m350::ui {

class GcodeHighlighter;

// A program's text with line numbers, the G-code colours, the line the machine (or the
// simulation) is running, and the parser's findings marked at their line and column.
class CodeView : public QPlainTextEdit {
    Q_OBJECT
public:
    struct Mark {
        int line = 0;   // 1-based
        int column = 0; // 1-based, in characters
        QString message;
    };
    CodeView(const gcode::Dialect& dialect, QWidget* parent = nullptr);

    // Replaces the text (the undo history too) and colours what is on screen.
    void setProgram(const QString& text);
    void setRunningLine(int line); // 0: none
    int runningLine() const { return runningLine_; }
    void setMarks(QVector<Mark> marks);
    const QVector<Mark>& marks() const { return marks_; }
    void goToLine(int line);
    int currentLine() const { return textCursor().blockNumber() + 1; }
    GcodeHighlighter* highlighter() const { return highlighter_; }

protected:
    void resizeEvent(QResizeEvent* event) override;
    bool event(QEvent* event) override;

private:
    friend class LineNumberArea;
    int gutterWidth() const;
    void paintGutter(QPaintEvent* event);
    void refreshSelections();

    QWidget* gutter_;
    GcodeHighlighter* highlighter_;
    int runningLine_ = 0;
    QVector<Mark> marks_;
};

} // namespace m350::ui
