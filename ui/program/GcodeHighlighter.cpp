#include "ui/program/GcodeHighlighter.h"

#include <QPlainTextEdit>
#include <QScrollBar>
#include <QTextBlock>
#include <QTextDocument>
#include <QTextLayout>

namespace m350::ui {

namespace {

// userState bits of a block (-1, Qt's default, reads as "neither")
constexpr int kInComment = 1; // the line starts inside /* */
constexpr int kFormatted = 2; // its formats match its text

int stateOf(const QTextBlock& block) { return block.userState() < 0 ? 0 : block.userState(); }

} // namespace

GcodeHighlighter::GcodeHighlighter(QPlainTextEdit* view, const gcode::Dialect& dialect)
    : QObject(view), view_(view), syntax_(dialect) {
    for (std::size_t kind = 0; kind < formats_.size(); ++kind) {
        formats_[kind] = format(static_cast<GcodeSyntax::Kind>(kind));
    }
    connect(view_->document(), &QTextDocument::contentsChange, this, &GcodeHighlighter::contentsChanged);
    connect(view_, &QPlainTextEdit::updateRequest, this, [this] { highlightVisible(); });
}

QTextCharFormat GcodeHighlighter::format(GcodeSyntax::Kind kind) {
    using Kind = GcodeSyntax::Kind;
    QTextCharFormat f;
    switch (kind) {
    case Kind::Word: f.setForeground(QColor("#7fc8ff")); f.setFontWeight(QFont::Bold); break;
    case Kind::Address: f.setForeground(QColor("#f0d060")); break;
    case Kind::Number: f.setForeground(QColor("#e8ecf0")); break;
    case Kind::Variable: f.setForeground(QColor("#ff9fd0")); break;
    case Kind::Keyword: f.setForeground(QColor("#ffa040")); f.setFontWeight(QFont::Bold); break;
    case Kind::Function: f.setForeground(QColor("#c0a0ff")); break;
    case Kind::Label: f.setForeground(QColor("#80f080")); f.setFontWeight(QFont::Bold); break;
    case Kind::Comment: f.setForeground(QColor("#7a8598")); f.setFontItalic(true); break;
    case Kind::Message: f.setForeground(QColor("#a0f0e0")); break;
    }
    return f;
}

bool GcodeHighlighter::startsInComment(const QTextBlock& block) const { return (stateOf(block) & kInComment) != 0; }

void GcodeHighlighter::reset() {
    bool inComment = false;
    for (QTextBlock block = view_->document()->begin(); block.isValid(); block = block.next()) {
        block.setUserState(inComment ? kInComment : 0);
        inComment = syntax_.blockCommentAfter(block.text(), inComment);
    }
    highlightVisible();
}

// An edit: the changed lines lose their formats, and the comment state flows down from the first
// of them until a line's state is what it was.
void GcodeHighlighter::contentsChanged(int position, int removed, int added) {
    (void)removed;
    if (formatting_) {
        return;
    }
    QTextDocument* doc = view_->document();
    QTextBlock block = doc->findBlock(position);
    const int changedEnd = position + added;
    bool inComment = block.previous().isValid()
                         ? syntax_.blockCommentAfter(block.previous().text(), startsInComment(block.previous()))
                         : false;
    while (block.isValid()) {
        int old = stateOf(block);
        bool changed = block.position() <= changedEnd;
        int now = inComment ? kInComment : 0;
        if (!changed && (old & kInComment) == now) {
            break;
        }
        block.setUserState(now); // not formatted
        inComment = syntax_.blockCommentAfter(block.text(), inComment);
        block = block.next();
    }
}

int GcodeHighlighter::highlightVisible() {
    if (formatting_) {
        return 0;
    }
    QTextBlock block = view_->cursorForPosition(QPoint(0, 0)).block();
    const QTextBlock last = view_->cursorForPosition(QPoint(0, view_->viewport()->height())).block();
    int count = 0;
    formatting_ = true;
    while (block.isValid()) {
        if ((stateOf(block) & kFormatted) == 0) {
            apply(block);
            ++count;
        }
        if (block == last) {
            break;
        }
        block = block.next();
    }
    formatting_ = false;
    return count;
}

void GcodeHighlighter::apply(QTextBlock& block) {
    std::vector<GcodeSyntax::Span> spans;
    syntax_.scan(block.text(), startsInComment(block), spans);
    QList<QTextLayout::FormatRange> ranges;
    ranges.reserve(static_cast<qsizetype>(spans.size()));
    for (const GcodeSyntax::Span& span : spans) {
        ranges.append({span.start, span.length, formats_[static_cast<std::size_t>(span.kind)]});
    }
    block.layout()->setFormats(ranges);
    block.setUserState(stateOf(block) | kFormatted);
    view_->document()->markContentsDirty(block.position(), block.length());
}

} // namespace m350::ui
