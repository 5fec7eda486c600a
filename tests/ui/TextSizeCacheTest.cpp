// The widgets that keep their text measurements (a softkey's size per label, a wrapped label's
// height per width) answer what Qt's own widgets answer, before and after a text or font change.
#include "ui/panel/SoftkeyButton.h"
#include "ui/widgets/MeasuredLabel.h"
#include "ui/widgets/WrappedLabel.h"

#include <QFont>
#include <QLabel>
#include <QPushButton>

#include <gtest/gtest.h>

namespace m350::test {

namespace {

const QString kShortHelp = QStringLiteral("F1 runs the line.");
const QString kLongHelp = QStringLiteral("The tool table's touch-off writes the Z of the tool in the spindle: jog the "
                                         "tool down onto the part, then F1; the value is the machine Z minus the work Z.");

int plainHeight(const QString& text, int width, const QFont& font) {
    QLabel label;
    label.setWordWrap(true);
    label.setFont(font);
    label.setText(text);
    return label.heightForWidth(width);
}

QSize plainButtonHint(const QString& text, bool enabled, const QFont& font) {
    QPushButton button;
    button.setFont(font);
    button.setText(text);
    button.setEnabled(enabled);
    return button.sizeHint();
}

// What a plain QLabel shaped as `like` answers for its text.
struct PlainAnswers {
    QSize size;
    QSize least;
    int heightAt150 = 0;
};
PlainAnswers plainAnswers(const QLabel& like) {
    QLabel label;
    label.setFont(like.font());
    label.setStyleSheet(like.styleSheet());
    label.setTextFormat(like.textFormat());
    label.setAlignment(like.alignment());
    label.setWordWrap(like.wordWrap());
    label.setIndent(like.indent());
    label.setMargin(like.margin());
    label.setMaximumWidth(like.maximumWidth());
    label.setText(like.text());
    return {label.sizeHint(), label.minimumSizeHint(), label.heightForWidth(150)};
}

void expectPlainAnswers(const ui::MeasuredLabel& label) {
    const PlainAnswers plain = plainAnswers(label);
    EXPECT_EQ(label.sizeHint(), plain.size) << label.text().toStdString();
    EXPECT_EQ(label.minimumSizeHint(), plain.least) << label.text().toStdString();
    EXPECT_EQ(label.heightForWidth(150), plain.heightAt150) << label.text().toStdString();
}

} // namespace

// A list's details shown row after row and back again (the Param page's cursor): every answer is
// the one a fresh QLabel gives, for texts kept, texts pushed out by newer ones, and after what
// else the size depends on changes (rich text, wrapping, alignment, indent, the widest allowed,
// the font, the style sheet).
TEST(MeasuredLabel, AnswersAsAQLabelForEveryTextShownAndEveryShape) {
    ui::MeasuredLabel label;
    QStringList texts;
    for (int row = 0; row < 100; ++row) {
        texts << QStringLiteral("Row %1: X-axis start acceleration %2 mm/s2").arg(row).arg(QString(row % 7, QLatin1Char('9')));
    }
    for (const QString& text : texts + texts.mid(90) + texts.mid(0, 5)) { // the last ten kept, the first five not
        label.setText(text);
        expectPlainAnswers(label);
    }
    label.setText(QStringLiteral("&nbsp;<span style='background:#3e5a8a;'>&nbsp;User(O)&nbsp;</span>"));
    expectPlainAnswers(label);
    label.setTextFormat(Qt::RichText);
    expectPlainAnswers(label);
    label.setText(kLongHelp);
    label.setTextFormat(Qt::PlainText);
    label.setWordWrap(true);
    expectPlainAnswers(label);
    label.setMaximumWidth(205); // QLabel itself measures again only at its next text
    label.setText(kShortHelp);
    expectPlainAnswers(label);
    label.setText(kLongHelp);
    expectPlainAnswers(label);
    label.setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    label.setIndent(12);
    label.setMargin(3);
    expectPlainAnswers(label);
    const QSize before = label.sizeHint();
    QFont font = label.font();
    font.setPointSize(font.pointSize() * 2);
    label.setFont(font);
    expectPlainAnswers(label);
    EXPECT_NE(label.sizeHint(), before);
    label.setStyleSheet(QStringLiteral("QLabel { font-size: 30pt; padding: 4px; }"));
    expectPlainAnswers(label);
}

TEST(WrappedLabel, AnswersAsAWrappedQLabelAsItsTextAndFontChange) {
    ui::WrappedLabel label;
    QFont font = label.font();
    label.setText(kLongHelp);
    for (int width : {120, 300, 120}) {
        EXPECT_EQ(label.heightForWidth(width), plainHeight(kLongHelp, width, font)) << width;
    }
    const int longAt120 = label.heightForWidth(120);
    label.setText(kShortHelp);
    EXPECT_EQ(label.heightForWidth(120), plainHeight(kShortHelp, 120, font));
    EXPECT_LT(label.heightForWidth(120), longAt120);
    font.setPointSize(font.pointSize() * 2);
    label.setFont(font);
    EXPECT_EQ(label.heightForWidth(120), plainHeight(kShortHelp, 120, font));
}

TEST(SoftkeyButton, SizesAsAPushButtonForEachLabelStateAndFont) {
    ui::SoftkeyButton button;
    QFont font = button.font();
    for (const QString& text : {QStringLiteral("F1 Out Open"), QStringLiteral("F2 参数"), QStringLiteral("F1 Out Open")}) {
        button.setText(text);
        EXPECT_EQ(button.sizeHint(), plainButtonHint(text, true, font)) << text.toStdString();
        button.setEnabled(false);
        EXPECT_EQ(button.sizeHint(), plainButtonHint(text, false, font)) << text.toStdString();
        button.setEnabled(true);
    }
    const QSize before = button.sizeHint();
    font.setPointSize(font.pointSize() * 2);
    button.setFont(font);
    EXPECT_EQ(button.sizeHint(), plainButtonHint(QStringLiteral("F1 Out Open"), true, font));
    EXPECT_GT(button.sizeHint().width(), before.width());
    QPushButton plain(QStringLiteral("F1 Out Open"));
    plain.setFont(font);
    EXPECT_EQ(button.minimumSizeHint(), plain.minimumSizeHint());
}

} // namespace m350::test
