// The widgets that keep their text measurements (a softkey's size per label, a wrapped label's
// height per width) answer what Qt's own widgets answer, before and after a text or font change.
#include "ui/panel/SoftkeyButton.h"
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

} // namespace

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
