// The PC keyboard as the panel's keys: one table (PanelKey::all()), every key of the panel in it
// once, documented in the README, and F12 stopping the machine on every page.
#include "tests/ui/PanelHarness.h"

#include "ui/actions/KeyboardMap.h"
#include "ui/actions/PanelKey.h"
#include "ui/panel/HandwheelWidget.h"
#include "ui/panel/KeyPad.h"
#include "ui/panel/SoftkeyBar.h"

#include <QKeyEvent>
#include <QKeySequence>
#include <QPushButton>
#include <QRegularExpression>
#include <QSet>
#include <QTest>

namespace m350::test {

namespace {

QString readme() { return fileText(QStringLiteral(M350_SOURCE_DIR "/README.md")); }

// The README's text between a heading and the next one.
QString section(const QString& text, const QString& heading) {
    const qsizetype from = text.indexOf(heading);
    if (from < 0) {
        return {};
    }
    const qsizetype to = text.indexOf(QStringLiteral("\n#"), from + heading.size());
    return text.mid(from, to < 0 ? -1 : to - from);
}

std::optional<ui::OperatorAction> press(QKeyCombination chord) {
    QKeyEvent event(QEvent::KeyPress, chord.key(), chord.keyboardModifiers());
    return ui::actionForKey(event, true);
}

double parameter(PanelHarness& panel, int number) { return panel.session().latest()->status.parameters.get(number); }

} // namespace

TEST(KeyboardMap, EveryPanelKeyHasItsOwnKeyboardChord) {
    QHash<int, QString> owner;
    for (const ui::PanelKey& key : ui::PanelKey::all()) {
        EXPECT_FALSE(key.keyboard.isEmpty()) << key.name.toStdString() << " has no keyboard key";
        for (QKeyCombination chord : key.keyboard) {
            const int combined = chord.toCombined();
            EXPECT_FALSE(owner.contains(combined))
                << QKeySequence(chord).toString().toStdString() << " is both " << owner.value(combined).toStdString()
                << " and " << key.name.toStdString();
            owner.insert(combined, key.name);
            auto action = press(chord);
            ASSERT_TRUE(action) << QKeySequence(chord).toString().toStdString() << " does nothing";
            if (key.role == ui::PanelKey::Role::Softkey) {
                EXPECT_EQ(action->kind, ui::OperatorAction::Kind::Softkey);
                EXPECT_EQ(action->softkey, key.softkey);
            } else {
                EXPECT_EQ(action->name, key.name) << QKeySequence(chord).toString().toStdString();
            }
        }
    }
    // the two kinds of chord outside the table: the second softkey row and the handwheel
    for (int number = 1; number <= 6; ++number) {
        QKeyCombination chord(Qt::ShiftModifier, Qt::Key(Qt::Key_F1 + number - 1));
        EXPECT_FALSE(owner.contains(chord.toCombined())) << "Shift+F" << number;
        auto action = press(chord);
        ASSERT_TRUE(action);
        EXPECT_EQ(action->softkey, number + 6);
    }
    for (Qt::Key arrow : {Qt::Key_Left, Qt::Key_Right}) {
        QKeyCombination chord(Qt::AltModifier, arrow);
        EXPECT_FALSE(owner.contains(chord.toCombined()));
        EXPECT_EQ(press(chord)->kind, ui::OperatorAction::Kind::Wheel);
    }
    EXPECT_EQ(owner.value(QKeyCombination(Qt::Key_F12).toCombined()), QStringLiteral("ESTOP"));
}

TEST(KeyboardMap, TheReadmeDocumentsEveryChordOnce) {
    const QString keys = section(readme(), QStringLiteral("### Keys and the handwheel"));
    ASSERT_FALSE(keys.isEmpty());
    for (const ui::PanelKey& key : ui::PanelKey::all()) {
        for (QKeyCombination chord : key.keyboard) {
            const QString text = QKeySequence(chord).toString(QKeySequence::PortableText);
            const QRegularExpression word(QStringLiteral("(^|[\\s|,/(])") + QRegularExpression::escape(text) +
                                          QStringLiteral("($|[\\s|,/)])"));
            EXPECT_TRUE(keys.contains(word)) << text.toStdString() << " (" << key.name.toStdString()
                                             << ") is not in the README's keyboard table";
        }
    }
    EXPECT_FALSE(readme().contains(QStringLiteral("(F12 steps"))) << "the Program page's 排序 is Shift+F6, F12 is E-STOP";
}

// With no key panel beside the screen (800x480) the handwheel's switches are keys too: Alt+Y and
// Alt+7 make the next detent move Y by ten wheel steps (param 172).
TEST(KeyboardMap, AltKeysSwitchTheHandwheelsAxisAndStep) {
    PanelHarness panel;
    panel.session().setParameter(171, 0.0); // every pulse runs out
    ui::settle(panel.session());
    panel.key("CONT_STEP_MPG");
    panel.key("CONT_STEP_MPG"); // CONT -> STEP -> MPG
    ASSERT_EQ(panel.session().latest()->status.jogMode, controller::JogMode::Mpg);
    QTest::keyClick(&panel.window(), Qt::Key_Y, Qt::AltModifier);
    QTest::keyClick(&panel.window(), Qt::Key_7, Qt::AltModifier);
    ui::HandwheelWidget* wheel = panel.window().keyPad()->handwheel();
    EXPECT_EQ(wheel->axis(), 1);
    EXPECT_EQ(wheel->step(), 10);
    const double y = panel.session().latest()->status.machine.y();
    QTest::keyClick(&panel.window(), Qt::Key_Left, Qt::AltModifier); // Y+ is at its limit after homing
    QTest::qWait(120); // the wheel sends what it gathered every 50 ms
    panel.advance(1.0);
    const double pulse = panel.session().latest()->status.parameters.get(172);
    EXPECT_NEAR(y - panel.session().latest()->status.machine.y(), 10 * pulse, 1e-9);
    EXPECT_TRUE(panel.window().findChild<QPushButton*>(QStringLiteral("wheelStep10"))->isChecked());
}

TEST(KeyboardMap, F12OnTheProgramPageIsEStopAndShiftF6Sorts) {
    PanelHarness panel;
    panel.key("PROGRAM");
    const double sort = parameter(panel, 149);
    QTest::keyClick(&panel.window(), Qt::Key_F6, Qt::ShiftModifier);
    ui::settle(panel.session());
    EXPECT_NE(parameter(panel, 149), sort) << "Shift+F6 is 排序: it steps param 149";
    EXPECT_NE(panel.window().state()["run"].toString(), QStringLiteral("estop"));
    EXPECT_TRUE(panel.window().softkeys()->label(12).startsWith(QStringLiteral("\u21e7F6 ")))
        << panel.window().softkeys()->label(12).toStdString();

    const double sorted = parameter(panel, 149);
    QTest::keyClick(&panel.window(), Qt::Key_F12);
    ui::settle(panel.session());
    EXPECT_EQ(parameter(panel, 149), sorted) << "F12 does not sort";
    EXPECT_EQ(panel.window().state()["run"].toString(), QStringLiteral("estop"));
}

TEST(KeyboardMap, PageAndOverrideKeysFromTheKeyboard) {
    PanelHarness panel;
    const QList<std::pair<QKeyCombination, QString>> pages{{QKeyCombination(Qt::ControlModifier, Qt::Key_O), "program"},
                                                           {QKeyCombination(Qt::ControlModifier, Qt::Key_R), "param"},
                                                           {QKeyCombination(Qt::ControlModifier, Qt::Key_L), "log"},
                                                           {QKeyCombination(Qt::ControlModifier, Qt::Key_Y), "system"}};
    for (const auto& [chord, page] : pages) {
        QTest::keyClick(&panel.window(), chord.key(), chord.keyboardModifiers());
        ui::settle(panel.session());
        EXPECT_EQ(panel.window().state()["page"].toString(), page);
    }
    QTest::keyClick(&panel.window(), Qt::Key_Equal, Qt::AltModifier);
    ui::settle(panel.session());
    EXPECT_EQ(panel.window().state()["spindle_override"].toDouble(), 110.0);
    QTest::keyClick(&panel.window(), Qt::Key_4, Qt::AltModifier);
    ui::settle(panel.session());
    EXPECT_DOUBLE_EQ(panel.session().latest()->status.jogStep, 1.0);
}

// Every key name the README's replay section lists is one a replay takes, and a replayed K1 or
// M8 does what a click on that key does.
TEST(ReplayKeys, EveryKeyTheReadmeListsIsAccepted) {
    const QString replays = section(readme(), QStringLiteral("### Command line, replays and state"));
    const qsizetype from = replays.indexOf(QStringLiteral("a panel key:"));
    const qsizetype to = replays.indexOf(QStringLiteral("{\"t\":1,\"key_down\""));
    ASSERT_GT(from, 0);
    ASSERT_GT(to, from);
    QString list = replays.mid(from + 12, to - from - 12);
    list.replace(QStringLiteral("K1-K7"), QStringLiteral("K1 K2 K3 K4 K5 K6 K7"));
    list.replace(QStringLiteral("F1-F6"), QStringLiteral("F1 F2 F3 F4 F5 F6"));
    list.replace(QStringLiteral("JOG_X+ .. JOG_B-"),
                 QStringLiteral("JOG_X+ JOG_X- JOG_Y+ JOG_Y- JOG_Z+ JOG_Z- JOG_A+ JOG_A- JOG_B+ JOG_B-"));
    const QStringList names = list.split(QRegularExpression(QStringLiteral("\\s+")), Qt::SkipEmptyParts);
    EXPECT_GT(names.size(), 60);
    QSet<QString> listed;
    for (const QString& name : names) {
        QString why;
        auto action = ui::OperatorAction::fromJson(QJsonObject{{"t", 0}, {"key", name}}, &why);
        EXPECT_TRUE(action) << name.toStdString() << ": " << why.toStdString();
        listed.insert(name);
    }
    for (const ui::PanelKey& key : ui::PanelKey::all()) {
        EXPECT_TRUE(listed.contains(key.name)) << key.name.toStdString() << " is missing from the README's replay keys";
    }
}

TEST(ReplayKeys, AReplayedKeyDoesWhatAClickDoes) {
    for (const QString& name : {QStringLiteral("K1"), QStringLiteral("M8")}) {
        PanelHarness replayed;
        PanelHarness clicked;
        QString why;
        auto action = ui::OperatorAction::fromJson(QJsonObject{{"t", 0}, {"key", name}}, &why);
        ASSERT_TRUE(action) << why.toStdString();
        replayed.act(*action);
        QPushButton* button = clicked.window().keyPad()->button(name);
        ASSERT_NE(button, nullptr) << name.toStdString();
        button->click();
        ui::settle(clicked.session());
        replayed.advance(5.0);
        clicked.advance(5.0);
        auto a = replayed.session().latest();
        auto b = clicked.session().latest();
        ASSERT_TRUE(a->log && b->log);
        ASSERT_FALSE(a->log->empty());
        EXPECT_EQ(a->log->back().event, b->log->back().event) << name.toStdString();
        EXPECT_EQ(a->log->back().detail, b->log->back().detail) << name.toStdString();
        EXPECT_EQ(a->status.outputs, b->status.outputs) << name.toStdString();
        for (int axis = 0; axis < 3; ++axis) {
            EXPECT_NEAR(a->status.machine(axis), b->status.machine(axis), 1e-9) << name.toStdString();
        }
    }
}

} // namespace m350::test
