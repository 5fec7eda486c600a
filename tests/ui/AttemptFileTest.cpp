// A training attempt's hash chain (ui/training/AttemptFile.h): what the panel records reads back
// chained; an edited, removed or unhashed line, another exercise's seed or another exam's key is
// refused at the line where the chain breaks.
#include "tests/ui/PanelHarness.h"
#include "ui/training/AttemptFile.h"

#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace m350::test {

namespace {

QByteArray recorded(const QByteArray& key) {
    ui::AttemptWriter writer("level = 1\n", key);
    QByteArray text = writer.header(QStringLiteral("pocket-taught-off"), QStringLiteral("王伟"));
    ui::OperatorAction start = ui::OperatorAction::key(QStringLiteral("START"));
    start.t = 1.5;
    text += writer.action(start);
    ui::OperatorAction typed = ui::OperatorAction::typed(QStringLiteral("T2"));
    typed.t = 2.0;
    text += writer.action(typed);
    text += writer.handIn(30.0, 1, false);
    return text;
}

QString written(const QTemporaryDir& dir, const QByteArray& text) {
    const QString path = dir.filePath(QStringLiteral("attempt.jsonl"));
    QFile file(path);
    EXPECT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(text);
    return path;
}

} // namespace

TEST(AttemptFile, WhatThePanelRecordsReadsBackChained) {
    QTemporaryDir dir;
    QString error;
    auto attempt = ui::readAttempt(written(dir, recorded("k")), "level = 1\n", "k", &error);
    ASSERT_TRUE(attempt) << error.toStdString();
    EXPECT_TRUE(attempt->chained);
    EXPECT_EQ(attempt->trainee, QStringLiteral("王伟"));
    EXPECT_EQ(attempt->exercise, QStringLiteral("pocket-taught-off"));
    ASSERT_EQ(attempt->actions.size(), 2u);
    EXPECT_EQ(attempt->actions[1].text, QStringLiteral("T2"));
    EXPECT_DOUBLE_EQ(attempt->timeUsed(), 30.0);
    EXPECT_EQ(attempt->hints, 1);
}

TEST(AttemptFile, AnEditedLineBreaksTheChainThere) {
    EnglishPanel english; // the refusals as the English panel says them
    QTemporaryDir dir;
    QByteArray text = recorded("k");
    text.replace("\"T2\"", "\"T3\"");
    QString error;
    EXPECT_FALSE(ui::readAttempt(written(dir, text), "level = 1\n", "k", &error));
    EXPECT_TRUE(error.contains(QStringLiteral("attempt.jsonl:3:"))) << error.toStdString();
    EXPECT_TRUE(error.contains(QStringLiteral("does not follow the chain"))) << error.toStdString();
}

TEST(AttemptFile, ARemovedLineOrAMissingHashIsRefused) {
    EnglishPanel english; // the refusals as the English panel says them
    QTemporaryDir dir;
    QList<QByteArray> lines = recorded("k").split('\n');
    QByteArray removed = lines[0] + '\n' + lines[2] + '\n' + lines[3] + '\n';
    QString error;
    EXPECT_FALSE(ui::readAttempt(written(dir, removed), "level = 1\n", "k", &error));
    EXPECT_TRUE(error.contains(QStringLiteral(":2:"))) << error.toStdString();
    QByteArray unhashed = lines[0] + '\n' + lines[1] + '\n' + "{\"t\":2,\"text\":\"T2\"}\n";
    EXPECT_FALSE(ui::readAttempt(written(dir, unhashed), "level = 1\n", "k", &error));
    EXPECT_TRUE(error.contains(QStringLiteral("no hash"))) << error.toStdString();
}

TEST(AttemptFile, AnotherExerciseOrExamKeyDoesNotFollow) {
    QTemporaryDir dir;
    const QString path = written(dir, recorded("k"));
    QString error;
    EXPECT_FALSE(ui::readAttempt(path, "level = 2\n", "k", &error));
    EXPECT_TRUE(error.contains(QStringLiteral(":1:"))) << error.toStdString();
    EXPECT_FALSE(ui::readAttempt(path, "level = 1\n", "other", &error));
}

TEST(AttemptFile, AHandMadeAttemptWithoutHashesReadsUnchained) {
    QTemporaryDir dir;
    QString error;
    auto attempt = ui::readAttempt(written(dir, "// by hand\n{\"t\":1,\"key\":\"START\"}\n"), "x", "", &error);
    ASSERT_TRUE(attempt) << error.toStdString();
    EXPECT_FALSE(attempt->chained);
    EXPECT_DOUBLE_EQ(attempt->timeUsed(), 1.0);
}

} // namespace m350::test
