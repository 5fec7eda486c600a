#pragma once

#include "ui/program/GcodeSyntax.h"

#include <QObject>
#include <QTextCharFormat>

#include <array>

class QPlainTextEdit;
class QTextBlock;

namespace m350::ui {

// Colours a program in its editor as it is shown: only the lines on screen are formatted (when
// they come into view or change), so a 100,000-line file opens at once and scrolls smoothly. The
// one thing that needs the lines above, whether a line starts inside `/* */`, is kept per line in
// the block's user state and updated from an edit downwards only as far as it changes.
class GcodeHighlighter : public QObject {
    Q_OBJECT
public:
    GcodeHighlighter(QPlainTextEdit* view, const gcode::Dialect& dialect);

    // After the whole text was replaced: every line's comment state, nothing formatted yet.
    void reset();
    // Formats the lines on screen that are not formatted yet; returns how many it formatted.
    int highlightVisible();
    static QTextCharFormat format(GcodeSyntax::Kind kind);
    // True while it changes formats: the document then signals contentsChange though no text changed.
    bool formatting() const { return formatting_; }

private:
    void contentsChanged(int position, int removed, int added);
    void apply(QTextBlock& block);
    bool startsInComment(const QTextBlock& block) const;

    QPlainTextEdit* view_;
    GcodeSyntax syntax_;
    std::array<QTextCharFormat, 9> formats_; // by GcodeSyntax::Kind
    bool formatting_ = false; // our own format changes also signal contentsChange
};

} // namespace m350::ui
