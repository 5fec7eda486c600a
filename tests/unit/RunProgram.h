#pragma once

// Shared driver for the language tests: build a machine (by hand or the bundled one), write the
// program to a temporary file, load it into a Controller, run it, and keep the controller so the
// variables stay inspectable after the run (also after an alarm).

#include "core/config/MachineConfig.h"
#include "core/params/ParameterNumbers.h"
#include "core/controller/Controller.h"
#include "core/controller/RunReport.h"
#include "core/controller/RunSettings.h"
#include "core/gcode/Diagnostic.h"
#include "core/gcode/Dialect.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <memory>
#include <string>
#include <system_error>
#include <utility>
#include <variant>
#include <vector>

namespace m350::test {

// An M350 with a 16-pocket magazine, G54 active, no libraries and all other parameters 0.
inline config::MachineConfig m350Machine() {
    config::MachineConfig config;
    config.name = "unit-test M350";
    config.dialect = &gcode::Dialect::m350();
    config.parameters.set(param::kMagazineCapacity, 16);
    config.parameters.set(param::kCurrentWorkSystem, 1);
    return config;
}

inline config::MachineConfig fanucMachine() {
    config::MachineConfig config;
    config.name = "unit-test FANUC";
    config.dialect = &gcode::Dialect::fanuc();
    return config;
}

// A machine folder loaded, or (a test failure said) the plain M350.
inline config::MachineConfig folderMachine(const std::string& folder) {
    auto loaded = config::loadMachineFolder(folder);
    if (const auto* error = std::get_if<config::ConfigError>(&loaded)) {
        ADD_FAILURE() << "cannot load machine folder " << folder << ": " << error->file << ": " << error->message;
        return m350Machine();
    }
    return std::get<config::MachineConfig>(std::move(loaded));
}

inline config::MachineConfig bundledMachine(const std::string& name = config::kDefaultMachine) {
    return folderMachine(config::bundledMachinesDirectory() + "/" + name);
}

// Lines joined with '\n', so line k of an alarm is element k-1.
inline std::string lines(std::initializer_list<std::string> text) {
    std::string out;
    for (const std::string& line : text) {
        out += line;
        out += '\n';
    }
    return out;
}

// Writes `text` to a file unique to the running test; returns the full path.
inline std::string writeTempFile(const std::string& text, const std::string& extension = ".nc") {
    static int counter = 0;
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    std::string name = "m350_";
    if (info) {
        name += std::string(info->test_suite_name()) + "_" + info->name();
    }
    for (char& ch : name) {
        if (ch == '/' || ch == '\\') {
            ch = '_';
        }
    }
    name += "_" + std::to_string(++counter) + extension;
    std::string path = testing::TempDir() + name;
    std::ofstream out(path, std::ios::binary);
    out << text;
    return path;
}

struct ProgramRun {
    std::unique_ptr<controller::Controller> controller;
    controller::RunReport report;
    bool loaded = false;
    std::string path;
    std::string fileName; // the base name, as alarms and diagnostics name the file

    macro::Value value(int number) const { return controller->variable(number); }
    double number(int number) const { return controller->variable(number).number; }
    bool vacant(int number) const { return controller->variable(number).vacant; }

    std::string diagnostics() const {
        std::string out;
        for (const gcode::Diagnostic& d : controller->diagnostics()) {
            out += gcode::formatDiagnostic(d) + "\n";
        }
        return out;
    }
    std::string alarmText() const {
        if (!report.alarm) {
            return "(no alarm)";
        }
        const Alarm& a = *report.alarm;
        return std::string(alarmKey(a.code)) + " at " + a.file + ":" + std::to_string(a.line) + ":" +
               std::to_string(a.column) + ": " + a.message;
    }
};

// Loads without asserting that loading succeeds (for tests of rejected programs).
inline ProgramRun loadProgram(config::MachineConfig config, const std::string& text,
                              controller::RunSettings settings = {}) {
    ProgramRun run;
    run.path = writeTempFile(text);
    run.fileName = std::filesystem::path(run.path).filename().string();
    run.controller = std::make_unique<controller::Controller>(std::move(config), std::move(settings));
    run.loaded = run.controller->loadFile(run.path);
    std::error_code ignored;
    std::filesystem::remove(run.path, ignored); // parsed once: the run no longer reads the file
    return run;
}

// Loads (which must succeed) and runs.
inline ProgramRun runProgram(config::MachineConfig config, const std::string& text,
                             controller::RunSettings settings = {}) {
    ProgramRun run = loadProgram(std::move(config), text, std::move(settings));
    EXPECT_TRUE(run.loaded) << "the program did not load:\n" << run.diagnostics();
    run.report = run.controller->run();
    return run;
}

inline ProgramRun runM350(const std::string& text, controller::RunSettings settings = {}) {
    return runProgram(m350Machine(), text, std::move(settings));
}

inline ProgramRun runFanuc(const std::string& text, controller::RunSettings settings = {}) {
    return runProgram(fanucMachine(), text, std::move(settings));
}

} // namespace m350::test

// Asserts a run ended normally, showing the alarm when it did not.
#define EXPECT_RUN_OK(run)                                                                                   \
    EXPECT_EQ((run).report.status, ::m350::controller::RunStatus::Ok) << (run).alarmText() << "\n"            \
                                                                      << (run).diagnostics()
