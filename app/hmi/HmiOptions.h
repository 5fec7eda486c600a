#pragma once

#include "core/controller/RunSettings.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace m350::hmi {

// The command line of `m350-hmi`.
struct HmiOptions {
    std::string program;     // loaded at start; START runs it
    std::string configDir;   // empty: the bundled default machine (a private copy of it)
    std::string language = "zh_CN";
    std::string page;        // monitor mdi io probe
    std::string programs;    // the Program page's U disk (U盘程序); empty: the home folder
    std::string screenshot;  // render, save the PNG, exit
    std::string replay;      // play operator actions (JSON Lines), then exit
    std::string state;       // write the panel's state (JSON) before exiting
    std::string record;      // record what the operator does (JSON Lines)
    bool unhomed = false;
    std::optional<int> tool;
    std::vector<std::string> breaks; // --break T1=0.62@12: tools that break in the simulated world
    double rate = 1.0;       // virtual seconds per wall second
    std::uint64_t dprntLimit = controller::RunSettings{}.externalOutputLimit; // bytes of DPRNT output dprnt.txt keeps
    int width = 1024, height = 600; // --size: the controller's screens are 800x480, 1024x600, 1280x800
    double measure = 0.0;    // > 0: start the program, measure the panel for this long, print JSON, exit
    bool eagerReplay = false; // --eager-replay: a replay as before, for comparing (much slower)
    // 训练 training: --exercise DIR with --attempt grades a recorded attempt headless (exit 0 pass,
    // 1 fail, 2 error) and writes --verdict; --exam FILE (exam.toml) checks the attempt's hash chain
    // with the exam's key and refuses an attempt without one. --training opens the training's start
    // page (with --exam, the exam); with --exercise and --replay it plays an attempt through it.
    bool training = false;
    std::string trainee;
    std::string exercises; // the exercises folder (default: the bundled ones)
    std::string attempts;  // where attempts and progress.json go (default: the user's data folder)
    std::string exercise;
    std::string attempt;
    std::string verdict;
    std::string exam;
    // --review ATTEMPT.jsonl with --exercise DIR: a trainer's review of the attempt (the review bar);
    // headless, played to --review-until T s (default: its end) and rendered
    std::string review;
    std::optional<double> reviewUntil;
    // --class-report FOLDER: every attempt under it graded, --report-csv and --report-html written
    std::string classReport;
    std::string reportCsv;
    std::string reportHtml;
    bool grading() const { return !exercise.empty() && !attempt.empty(); }
    bool headlessRun() const { return !screenshot.empty() || !replay.empty() || !state.empty(); }
};

struct HmiParse {
    std::optional<HmiOptions> options;
    int exitStatus = 0;
};
HmiParse parseHmiCommandLine(int argc, char** argv);

} // namespace m350::hmi
