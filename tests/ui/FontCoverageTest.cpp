// Every Chinese word on each screen must be drawable with the font the panel picked: a machine
// without a CJK font shows boxes, and this test fails there instead of the operator finding out.
#include "tests/ui/PanelHarness.h"

#include <QAbstractButton>
#include <QFontMetrics>
#include <QLabel>
#include <QTableWidget>

namespace m350::test {

namespace {

QStringList missingGlyphs(QWidget* root) {
    QStringList missing;
    auto check = [&missing](const QString& text, const QFont& font, const QString& where) {
        QFontMetrics metrics(font);
        for (uint code : text.toUcs4()) {
            if (code > 0x7f && !metrics.inFontUcs4(code)) {
                missing << QStringLiteral("%1: U+%2 in \"%3\"").arg(where).arg(code, 4, 16, QLatin1Char('0')).arg(text);
                return;
            }
        }
    };
    for (QLabel* label : root->findChildren<QLabel*>()) {
        if (label->isVisibleTo(root)) {
            check(label->text(), label->font(), label->objectName());
        }
    }
    for (QAbstractButton* button : root->findChildren<QAbstractButton*>()) {
        if (button->isVisibleTo(root)) {
            check(button->text(), button->font(), button->objectName());
        }
    }
    for (QTableWidget* table : root->findChildren<QTableWidget*>()) {
        for (int row = 0; row < table->rowCount(); ++row) {
            for (int col = 0; col < table->columnCount(); ++col) {
                if (auto* item = table->item(row, col)) {
                    check(item->text(), table->font(), table->objectName());
                }
            }
        }
    }
    return missing;
}

} // namespace

TEST(FontCoverage, APanelFontWithChineseIsPicked) {
    ASSERT_NE(PanelHarness::language(), nullptr);
    EXPECT_FALSE(PanelHarness::language()->cjkFamily().isEmpty()) << PanelHarness::language()->fontProblem().toStdString();
}

TEST(FontCoverage, EveryChineseCharacterOnEachScreenHasAGlyph) {
    PanelHarness panel;
    for (const char* page : {"monitor", "mdi", "io", "probe", "param", "system"}) {
        panel.page(QString::fromLatin1(page));
        QStringList missing = missingGlyphs(&panel.window());
        EXPECT_TRUE(missing.isEmpty()) << page << ": " << missing.join("; ").toStdString();
    }
}

TEST(FontCoverage, TheChineseScreensAreReallyInChinese) {
    PanelHarness panel;
    int chinese = 0;
    for (QLabel* label : panel.window().findChildren<QLabel*>()) {
        for (QChar c : label->text()) {
            chinese += c.unicode() >= 0x4e00 && c.unicode() <= 0x9fff ? 1 : 0;
        }
    }
    EXPECT_GT(chinese, 30);
}

} // namespace m350::test
