// GoogleTest main for the panel tests: one QApplication on the offscreen platform, in Chinese
// (the panel's default), with the panel's style sheet.
#include "tests/ui/PanelHarness.h"
#include "ui/panel/PanelStyle.h"
#include "ui/panel/QuietOffscreen.h"

#include <QApplication>

#include <gtest/gtest.h>

int main(int argc, char** argv) {
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    m350::ui::installQuietOffscreen(); // as m350-hmi: no platform note per page switch in the test log
    m350::ui::Language language(app);
    m350::test::PanelHarness::setLanguage(&language);
    language.set(QStringLiteral("zh_CN"));
    app.setStyleSheet(m350::ui::panelStyleSheet());
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
