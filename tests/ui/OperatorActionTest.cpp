// The replay line format: every kind of action reads back as it was written; bad lines say why.
#include "tests/ui/PanelHarness.h"
#include "ui/actions/OperatorAction.h"
#include "ui/actions/PanelKey.h"
#include "ui/pages/PageTable.h"
#include "ui/replay/Replay.h"

#include <QJsonDocument>
#include <QTemporaryFile>

#include <gtest/gtest.h>

namespace m350::test {

using ui::OperatorAction;

namespace {

std::optional<OperatorAction> parse(const char* json, QString* error = nullptr) {
    QString ignored;
    return OperatorAction::fromJson(QJsonDocument::fromJson(json).object(), error ? error : &ignored);
}

} // namespace

TEST(OperatorAction, ReadsTheIssuesExamples) {
    auto key = parse(R"({"t":0,"key":"MDI"})");
    ASSERT_TRUE(key);
    EXPECT_EQ(key->kind, OperatorAction::Kind::Key);
    EXPECT_EQ(key->name, "MDI");
    auto wheel = parse(R"({"t":2,"wheel":{"axis":"X","step":10,"detents":40,"seconds":1}})");
    ASSERT_TRUE(wheel);
    EXPECT_EQ(wheel->kind, OperatorAction::Kind::Wheel);
    EXPECT_EQ(wheel->wheel.axis, 0);
    EXPECT_EQ(wheel->wheel.step, 10);
    EXPECT_EQ(wheel->wheel.detents, 40);
    EXPECT_DOUBLE_EQ(wheel->wheel.seconds, 1.0);
    EXPECT_DOUBLE_EQ(wheel->t, 2.0);
    auto force = parse(R"({"t":3.5,"force":{"input":11,"level":0}})");
    ASSERT_TRUE(force);
    EXPECT_EQ(force->force.input, 11);
    EXPECT_EQ(force->force.fault, "stuck");
    auto press = parse(R"({"t":4,"force":{"input":14,"fault":"pressed","level":1,"seconds":0.3}})");
    ASSERT_TRUE(press); // an exercise's [[faults]] "pressed" plays as this action: the level for the seconds, once
    EXPECT_EQ(press->force.fault, "pressed");
    EXPECT_EQ(press->force.level, 1);
    EXPECT_DOUBLE_EQ(press->force.seconds, 0.3);
    auto wait = parse(R"({"t":8})");
    ASSERT_TRUE(wait);
    EXPECT_EQ(wait->kind, OperatorAction::Kind::Wait);
    auto softkey = parse(R"({"t":0.4,"softkey":1})");
    ASSERT_TRUE(softkey);
    EXPECT_EQ(softkey->softkey, 1);
}

TEST(OperatorAction, WritesWhatItReads) {
    for (const char* json : {R"({"t":1.5,"key":"JOG_Z-"})", R"({"t":1,"key_down":"JOG_X+"})",
                             R"({"t":0,"page":"io"})", R"({"t":0,"text":"G0 X10"})", R"({"t":0,"lang":"en"})",
                             R"({"t":2,"force":{"input":13,"fault":"slow","seconds":2}})",
                             R"({"t":3,"force":{"input":14,"fault":"pressed","level":1,"seconds":0.3}})"}) {
        auto action = parse(json);
        ASSERT_TRUE(action) << json;
        auto again = OperatorAction::fromJson(action->toJson(), nullptr);
        ASSERT_TRUE(again) << json;
        EXPECT_EQ(QJsonDocument(again->toJson()).toJson(), QJsonDocument(action->toJson()).toJson()) << json;
    }
}

TEST(OperatorAction, RefusesWhatItDoesNotKnow) {
    EnglishPanel english; // the refusals as the English panel says them
    QString error;
    EXPECT_FALSE(parse(R"({"t":0,"key":"LAUNCH"})", &error));
    EXPECT_TRUE(error.contains("LAUNCH"));
    EXPECT_FALSE(parse(R"({"key":"START"})", &error));
    EXPECT_TRUE(error.contains("\"t\""));
    EXPECT_FALSE(parse(R"({"t":0,"softkey":13})", &error));
    EXPECT_FALSE(parse(R"({"t":0,"wheel":{"axis":"Q","step":1,"detents":1}})", &error));
    EXPECT_FALSE(parse(R"({"t":0,"key":"START","page":"io"})", &error));
    EXPECT_TRUE(error.contains("one action per line"));
}

TEST(Replay, AReplayFileErrorNamesTheLine) {
    EnglishPanel english; // the refusals as the English panel says them
    QTemporaryFile file;
    ASSERT_TRUE(file.open());
    file.write("{\"t\":0,\"key\":\"MDI\"}\n\n// a comment\n{\"t\":1,\"key\":\"NOPE\"}\n");
    file.close();
    QString error;
    EXPECT_FALSE(ui::readReplay(file.fileName(), &error));
    EXPECT_TRUE(error.contains(QStringLiteral(":4:8: unknown key \"NOPE\""))) << error.toStdString();
}

TEST(Replay, ActionsMustBeInTimeOrder) {
    EnglishPanel english; // the refusals as the English panel says them
    QTemporaryFile file;
    ASSERT_TRUE(file.open());
    file.write("{\"t\":2}\n{\"t\":1}\n");
    file.close();
    QString error;
    EXPECT_FALSE(ui::readReplay(file.fileName(), &error));
    EXPECT_TRUE(error.contains(":2:2: t = 1 comes before")) << error.toStdString(); // at its "t"
}

// The key table is the replay format's vocabulary: every key reads back by its name, once, and a
// page key opens a page the panel has.
TEST(PanelKey, EveryKeyIsKnownByItsNameAndEveryPageKeyHasItsPage) {
    QStringList names;
    for (const ui::PanelKey& key : ui::PanelKey::all()) {
        EXPECT_FALSE(names.contains(key.name)) << key.name.toStdString();
        names << key.name;
        EXPECT_EQ(ui::PanelKey::named(key.name), &key);
        auto action = parse(QStringLiteral(R"({"t":0,"key":"%1"})").arg(key.name).toUtf8().constData());
        EXPECT_TRUE(action) << key.name.toStdString();
        if (key.role == ui::PanelKey::Role::Page) {
            EXPECT_TRUE(ui::PageTable::ids().contains(QString(key.page))) << key.name.toStdString();
        }
        if (key.role == ui::PanelKey::Role::Machine) {
            EXPECT_NE(key.command, nullptr) << key.name.toStdString();
        }
    }
    EXPECT_EQ(ui::PanelKey::named(QStringLiteral("LAUNCH")), nullptr);
}

} // namespace m350::test
