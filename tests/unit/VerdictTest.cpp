// The checks graded on an attempt's facts (core/training/Verdict.h): a repaired line counts as the
// controller reads it, the operator's own RESET is no alarm, a response is timed from the alarm.
#include "core/training/Verdict.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace m350::test {

namespace {

namespace fs = std::filesystem;

training::Check checkOf(training::Check::Kind kind, const std::string& id) {
    training::Check check;
    check.kind = kind;
    check.id = id;
    check.why = {"错", "wrong"};
    return check;
}

} // namespace

TEST(Verdict, ARepairedLineCountsWhateverItsSpacingCaseOrComment) {
    const fs::path folder = fs::path(testing::TempDir()) / ("verdict-line-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
    fs::create_directories(folder);
    std::ofstream(folder / "slib-g.nc") << "O20000\nG53Y#1309   f#1311 //my own note\nG53 Y#1309 F#1312\n";
    training::Exercise exercise;
    training::Check same = checkOf(training::Check::Kind::FileLine, "same");
    same.file = "slib-g.nc";
    same.line = 2;
    same.text = "G53 Y#1309 F#1311 //to the Y pre-point";
    training::Check other = same;
    other.id = "other";
    other.line = 3;
    exercise.checks = {same, other};
    training::AttemptFacts facts;
    facts.machineFolder = folder.string();
    const training::Verdict verdict = training::gradeAttempt(exercise, facts);
    ASSERT_EQ(verdict.checks.size(), 2u);
    EXPECT_TRUE(verdict.checks[0].passed) << verdict.checks[0].measured;
    EXPECT_FALSE(verdict.checks[1].passed) << "F#1312 is another block";
    EXPECT_EQ(verdict.checks[1].reason.english, "wrong");
    EXPECT_EQ(verdict.checks[1].target.line, 3);
    EXPECT_EQ(verdict.score, 50);
    fs::remove_all(folder);
}

TEST(Verdict, TheOperatorsResetIsNoAlarmAndAResponseIsTimedFromTheAlarm) {
    training::Exercise exercise;
    exercise.timeLimit = 100;
    training::Check none = checkOf(training::Check::Kind::NoAlarm, "no-alarm");
    training::Check reset = checkOf(training::Check::Kind::Responded, "reset");
    reset.key = "RESET";
    reset.code = "sensor_timeout";
    reset.within = 15;
    exercise.checks = {none, reset};
    training::AttemptFacts facts;
    controller::RunEvents::Event operatorReset;
    operatorReset.time = 2;
    operatorReset.alarm.code = AlarmCode::OperatorReset;
    facts.events.push_back(operatorReset);
    facts.keys = {{1.0, "RESET"}, {40.0, "RESET"}};
    EXPECT_TRUE(training::gradeAttempt(exercise, facts).checks[0].passed);
    EXPECT_FALSE(training::gradeAttempt(exercise, facts).checks[1].passed) << "no sensor alarm came";

    controller::RunEvents::Event timeout;
    timeout.time = 30;
    timeout.alarm.code = AlarmCode::SensorTimeout;
    timeout.alarm.file = "slib-g.nc";
    timeout.alarm.line = 46;
    facts.events.push_back(timeout);
    const training::Verdict verdict = training::gradeAttempt(exercise, facts);
    EXPECT_FALSE(verdict.checks[0].passed);
    EXPECT_EQ(verdict.checks[0].target.file, "slib-g.nc");
    EXPECT_TRUE(verdict.checks[1].passed) << verdict.checks[1].measured << ": the RESET at 40 s, 10 s after the alarm";
    EXPECT_EQ(verdict.checks[1].measured, "sensor_timeout → RESET 10 s");
    facts.keys = {{1.0, "RESET"}, {46.0, "RESET"}};
    EXPECT_FALSE(training::gradeAttempt(exercise, facts).checks[1].passed) << "16 s is too late";
}

} // namespace m350::test
