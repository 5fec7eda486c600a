#include "app/hmi/HmiOptions.h"

#include "app/sim/ByteLimitOption.h"
#include "ui/pages/PageTable.h"
#include "ui/replay/Replay.h"

#include <CLI/CLI.hpp>

#include <cmath>

namespace m350::hmi {

HmiParse parseHmiCommandLine(int argc, char** argv) {
    HmiOptions o;
    std::vector<std::string> pages; // every page a replay may open
    for (const QString& id : ui::PageTable::ids()) {
        pages.push_back(id.toStdString());
    }
    CLI::App app{"m350-hmi: the M350 panel (desktop). With --screenshot, --replay or --state it renders "
                 "and exits, for tests and docs."};
    app.set_version_flag("--version", std::string("m350-hmi ") + M350_VERSION + " (commit " + M350_COMMIT + ")");
    app.add_option("program", o.program, "G-code file to load; START runs it")->check(CLI::ExistingFile);
    app.add_option("--config", o.configDir, "machine folder (default: the bundled M350 16-pocket linear rack)")
        ->check(CLI::ExistingDirectory);
    app.add_option("--lang", o.language, "language of the panel")->check(CLI::IsMember({"zh_CN", "en"}));
    app.add_option("--page", o.page, "page to show")->check(CLI::IsMember(pages));
    app.add_option("--programs", o.programs, "the Program page's U disk (default: the home folder)")
        ->check(CLI::ExistingDirectory);
    app.add_option("--screenshot", o.screenshot, "save the window as a PNG and exit");
    app.add_option_function<std::string>(
           "--size",
           [&o](const std::string& size) {
               const std::size_t x = size.find('x');
               try {
                   o.width = x == std::string::npos ? 0 : std::stoi(size.substr(0, x));
                   o.height = x == std::string::npos ? 0 : std::stoi(size.substr(x + 1));
               } catch (const std::exception&) {
                   o.width = o.height = 0;
               }
               if (o.width < 640 || o.height < 400 || o.width > 4096 || o.height > 4096) {
                   throw CLI::ValidationError("--size", "give WIDTHxHEIGHT in pixels, 640x400 to 4096x4096 (800x480)");
               }
           },
           "the window's size, WIDTHxHEIGHT (default 1024x600; the controller's screens: 800x480, 1024x600, 1280x800)");
    app.add_option("--replay", o.replay, "play operator actions (JSON Lines) in virtual time, then exit")
        ->check(CLI::ExistingFile);
    app.add_flag("--eager-replay", o.eagerReplay,
                 "play a replay as m350-hmi did before: the panel laid out after every action, the machine in a "
                 "thread of its own, every file of the scratch machine folder synced (much slower; to check that "
                 "the fast way ends the same)");
    app.add_option("--state", o.state, "write the panel's state as JSON and exit");
    app.add_flag("--training", o.training, "训练 Training: the exercises' start page (with --exam, the exam)");
    app.add_option("--trainee", o.trainee, "the trainee's name (training: the attempts are kept under it)");
    app.add_option("--exercises", o.exercises, "the training's exercises folder (default: the bundled exercises)")
        ->check(CLI::ExistingDirectory);
    app.add_option("--attempts", o.attempts, "where the training keeps attempts and progress (default: the user's data folder)");
    CLI::Option* exercise = app.add_option("--exercise", o.exercise, "a training exercise folder (resources/exercises/NAME)")
        ->check(CLI::ExistingDirectory);
    CLI::Option* attempt =
        app.add_option("--attempt", o.attempt,
                       "with --exercise: grade this recorded attempt without a window, exit 0 pass, 1 fail, 2 error")
            ->check(CLI::ExistingFile)
            ->needs(exercise);
    CLI::Option* review =
        app.add_option("--review", o.review,
                       "a trainer's review of this recorded attempt on its exercise's machine (--exercise, else the "
                       "one its first line names among --exercises), 1x-50x, pause, one block at a time (Space, '.', "
                       "'+', '-', F8 the view)")
            ->check(CLI::ExistingFile);
    app.add_option("--review-until", o.reviewUntil,
                   "with --review and --screenshot or --state: play the attempt to this many seconds (default: its end)")
        ->check(CLI::Range(0.0, ui::kMostReplaySeconds))
        ->needs(review);
    app.add_option("--verdict", o.verdict, "with --attempt: write the verdict (JSON) here")->needs(attempt);
    CLI::Option* report = app.add_option("--class-report", o.classReport,
                                         "grade every attempt (*.jsonl) under this folder for a class report (with "
                                         "--exercises, default the bundled ones)")
                              ->check(CLI::ExistingDirectory);
    app.add_option("--report-csv", o.reportCsv, "with --class-report: the report as CSV")->needs(report);
    app.add_option("--report-html", o.reportHtml, "with --class-report: the report as one self-contained HTML page")->needs(report);
    app.add_option("--exam", o.exam,
                   "an exam (exam.toml: exercises, time_limit, key): with --training the exam's exercises, no hints; "
                   "with --attempt an attempt must carry the exam's intact hash chain")
        ->check(CLI::ExistingFile);
    app.add_option("--record", o.record, "record the operator's actions to this file (JSON Lines)");
    app.add_flag("--unhomed", o.unhomed, "start with no axis homed, as after power-on");
    app.add_option("--tool", o.tool, "tool in the spindle at start")->check(CLI::Range(0, 99));
    app.add_option("--break", o.breaks,
                   "tool N breaks in the simulated world, L mm shorter and cutting nothing: T1=0.62 or T1=0.62@12 "
                   "(at 12 s of virtual time), repeatable");
    sim::addByteLimitOption(app, "--dprnt-limit", o.dprntLimit, sim::kMostExternalOutputBytes,
                            "the most bytes of DPRNT output the machine folder's dprnt.txt keeps (default 64M; K, M, "
                            "G suffixes); the system log still gets every record");
    app.add_option("--rate", o.rate, "virtual seconds per wall second (faster for simulation)")
        ->check(CLI::Range(0.01, 1000.0));
    app.add_option("--measure", o.measure,
                   "run the loaded program for this many seconds and print the panel's frame rate, CPU and "
                   "latency as JSON (tests/bench/panel_perf.sh)")
        ->check(CLI::Range(0.1, 600.0));
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return {std::nullopt, app.exit(e) == 0 ? 0 : 64};
    }
    return {o, 0};
}

} // namespace m350::hmi
