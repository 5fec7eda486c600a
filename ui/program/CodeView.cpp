#include "ui/program/CodeView.h"

#include "ui/program/GcodeHighlighter.h"

#include <QHelpEvent>
#include <QPainter>
#include <QTextBlock>
#include <QToolTip>

#include <algorithm>

namespace m350::ui {

class LineNumberArea : public QWidget {
public:
    explicit LineNumberArea(CodeView* view) : QWidget(view), view_(view) {}
    QSize sizeHint() const override { return {view_->gutterWidth(), 0}; }

protected:
    void paintEvent(QPaintEvent* event) override { view_->paintGutter(event); }

private:
    CodeView* view_;
};

CodeView::CodeView(const gcode::Dialect& dialect, QWidget* parent) : QPlainTextEdit(parent) {
    setObjectName("codeView");
    setLineWrapMode(QPlainTextEdit::NoWrap);
    setTabChangesFocus(false);
    setFocusPolicy(Qt::ClickFocus); // the panel's keys reach it through the dispatcher
    QFont mono(QStringLiteral("DejaVu Sans Mono"));
    mono.setStyleHint(QFont::Monospace);
    mono.setPointSize(11);
    setFont(mono);
    setStyleSheet(QStringLiteral("QPlainTextEdit { background: #060a10; color: #e8ecf0; }"));
    gutter_ = new LineNumberArea(this);
    highlighter_ = new GcodeHighlighter(this, dialect);
    connect(this, &QPlainTextEdit::blockCountChanged, this, [this] { setViewportMargins(gutterWidth(), 0, 0, 0); });
    connect(this, &QPlainTextEdit::updateRequest, this, [this](const QRect& rect, int dy) {
        dy ? gutter_->scroll(0, dy) : gutter_->update(0, rect.y(), gutter_->width(), rect.height());
    });
    setViewportMargins(gutterWidth(), 0, 0, 0);
}

void CodeView::setProgram(const QString& text) {
    runningLine_ = 0;
    marks_.clear();
    setPlainText(text);
    highlighter_->reset();
    refreshSelections();
}

int CodeView::gutterWidth() const {
    int digits = static_cast<int>(QString::number(std::max(1, blockCount())).size());
    return 14 + fontMetrics().horizontalAdvance(QLatin1Char('9')) * std::max(3, digits);
}

void CodeView::resizeEvent(QResizeEvent* event) {
    QPlainTextEdit::resizeEvent(event);
    QRect r = contentsRect();
    gutter_->setGeometry(QRect(r.left(), r.top(), gutterWidth(), r.height()));
}

void CodeView::paintGutter(QPaintEvent* event) {
    QPainter painter(gutter_);
    painter.fillRect(event->rect(), QColor("#1b2029"));
    QTextBlock block = firstVisibleBlock();
    int top = qRound(blockBoundingGeometry(block).translated(contentOffset()).top());
    const int height = fontMetrics().height();
    while (block.isValid() && top <= event->rect().bottom()) {
        int line = block.blockNumber() + 1;
        bool marked = std::any_of(marks_.begin(), marks_.end(), [line](const Mark& m) { return m.line == line; });
        if (line == runningLine_) {
            painter.fillRect(0, top, gutter_->width(), height, QColor("#2f5f2f"));
        }
        painter.setPen(marked ? QColor("#ff6060") : QColor("#7a8598"));
        painter.drawText(0, top, gutter_->width() - 6, height, Qt::AlignRight, QString::number(line));
        top += qRound(blockBoundingRect(block).height());
        block = block.next();
    }
}

void CodeView::setRunningLine(int line) {
    if (line == runningLine_) {
        return;
    }
    runningLine_ = line;
    if (line > 0) {
        // the view follows the run only while the operator is not editing elsewhere
        QTextBlock block = document()->findBlockByNumber(line - 1);
        if (block.isValid() && isReadOnly()) {
            QTextCursor cursor(block);
            setTextCursor(cursor);
            centerCursor();
        }
    }
    refreshSelections();
    gutter_->update();
}

void CodeView::setMarks(QVector<Mark> marks) {
    marks_ = std::move(marks);
    refreshSelections();
    gutter_->update();
}

void CodeView::goToLine(int line) {
    QTextBlock block = document()->findBlockByNumber(std::clamp(line, 1, blockCount()) - 1);
    setTextCursor(QTextCursor(block));
    centerCursor();
}

void CodeView::refreshSelections() {
    QList<QTextEdit::ExtraSelection> selections;
    if (runningLine_ > 0) {
        QTextBlock block = document()->findBlockByNumber(runningLine_ - 1);
        if (block.isValid()) {
            QTextEdit::ExtraSelection running;
            running.format.setBackground(QColor("#24452a"));
            running.format.setProperty(QTextFormat::FullWidthSelection, true);
            running.cursor = QTextCursor(block);
            selections.append(running);
        }
    }
    for (const Mark& mark : marks_) {
        QTextBlock block = document()->findBlockByNumber(mark.line - 1);
        if (!block.isValid()) {
            continue;
        }
        // from the column to the end of its word (the whole line when the column is unknown)
        const QString text = block.text();
        int from = std::clamp(mark.column - 1, 0, static_cast<int>(text.size()));
        int to = mark.column > 0 ? from + 1 : static_cast<int>(text.size());
        while (to < text.size() && !text.at(to).isSpace()) {
            ++to;
        }
        QTextEdit::ExtraSelection error;
        error.format.setUnderlineStyle(QTextCharFormat::WaveUnderline);
        error.format.setUnderlineColor(QColor("#ff4040"));
        error.format.setBackground(QColor("#4a1818"));
        error.cursor = QTextCursor(block);
        error.cursor.setPosition(block.position() + from);
        error.cursor.setPosition(block.position() + std::min(to, static_cast<int>(text.size())), QTextCursor::KeepAnchor);
        selections.append(error);
    }
    setExtraSelections(selections);
}

// Hovering a marked line shows what the parser says about it.
bool CodeView::event(QEvent* event) {
    if (event->type() == QEvent::ToolTip) {
        auto* help = static_cast<QHelpEvent*>(event);
        int line = cursorForPosition(viewport()->mapFromGlobal(help->globalPos())).blockNumber() + 1;
        QStringList texts;
        for (const Mark& mark : marks_) {
            if (mark.line == line) {
                texts << mark.message;
            }
        }
        texts.isEmpty() ? QToolTip::hideText() : QToolTip::showText(help->globalPos(), texts.join('\n'), this);
        return true;
    }
    return QPlainTextEdit::event(event);
}

} // namespace m350::ui
