#include "app/sim/ToolsCommand.h"
#include "app/sim/ExitStatus.h"

#include "app/sim/ReportJson.h"

#include "core/common/EchoText.h"
#include "core/files/OutputFile.h"
#include "core/tools/ToolTableFile.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <iostream>

namespace m350::sim {

namespace {

nlohmann::json optional(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); }

nlohmann::json entryJson(const tools::ToolEntry& entry) {
    nlohmann::json offsets = nlohmann::json::object();
    for (std::size_t axis = 0; axis < tools::kOffsetLetters.size(); ++axis) {
        if (entry.offsets[axis]) {
            offsets[std::string(1, tools::kOffsetLetters[axis])] = *entry.offsets[axis];
        }
    }
    return {{"tool", entry.tool},
            {"pocket", entry.pocket},
            {"z", entry.offset(tools::kZ)},
            {"offsets", offsets},
            {"diameter", optional(entry.diameter)},
            {"front_angle", optional(entry.frontAngle)},
            {"back_angle", optional(entry.backAngle)},
            {"orientation", entry.orientation ? nlohmann::json(*entry.orientation) : nlohmann::json(nullptr)},
            {"max_rpm", optional(entry.maxRpm)},
            {"teeth", entry.teeth ? nlohmann::json(*entry.teeth) : nlohmann::json(nullptr)},
            {"type", entry.type ? nlohmann::json(std::string(tools::toolTypeKey(*entry.type))) : nlohmann::json(nullptr)},
            {"comment", clipEcho(entry.comment)}}; // a comment of a megabyte is not repeated whole
}

// The file the table came from, and its issues read again with their kinds.
std::filesystem::path tableFile(const SimOptions& o, const config::MachineConfig& machine) {
    return o.toolTableFile ? std::filesystem::path(*o.toolTableFile)
                           : std::filesystem::path(machine.folder) / tools::kToolTableFileName;
}

} // namespace

std::optional<Message> useToolTableFile(const SimOptions& o, config::MachineConfig& machine) {
    if (!o.toolTableFile) {
        return std::nullopt;
    }
    auto read = tools::readToolTableFile(*o.toolTableFile);
    if (auto* error = std::get_if<Message>(&read)) {
        return *error;
    }
    auto& parsed = std::get<tools::ParsedToolTable>(read);
    for (const tools::ToolTableIssue& issue : parsed.issues) {
        std::cerr << tools::formatIssue(issue, o.language) << '\n';
    }
    machine.toolTable = std::move(parsed.table);
    machine.toolTableFile = *o.toolTableFile;
    return std::nullopt;
}

int listTools(controller::Controller& controller, const SimOptions& o) {
    const config::MachineConfig machine = controller.config();
    const std::filesystem::path file = tableFile(o, machine);
    nlohmann::json issues = nlohmann::json::array();
    bool skipped = false;
    std::error_code ec;
    if (std::filesystem::is_regular_file(file, ec)) {
        auto read = tools::readToolTableFile(file);
        if (auto* parsed = std::get_if<tools::ParsedToolTable>(&read)) {
            for (const tools::ToolTableIssue& issue : parsed->issues) {
                const bool error = issue.severity == tools::ToolTableIssue::Severity::Error;
                skipped |= error;
                issues.push_back({{"severity", error ? "error" : "warning"},
                                  {"file", issue.file},
                                  {"line", issue.line},
                                  {"column", issue.column},
                                  {"message", issue.message}});
                if (!issue.words.id.empty()) {
                    issues.back()["message_id"] = issue.words.id;
                }
                if (issue.omitted > 0) {
                    issues.back()["omitted"] = issue.omitted; // as `check` marks the findings it left out
                }
            }
        }
    }
    const tools::ToolTable table = controller.toolTableEdits().table();
    if (o.toolsAsTable) {
        std::cout << tools::formatToolTable(table);
        return skipped ? kExitError : kExitOk;
    }
    nlohmann::json rows = nlohmann::json::array();
    for (const tools::ToolEntry& entry : table.entries()) {
        rows.push_back(entryJson(entry));
    }
    const bool fromFile = std::filesystem::is_regular_file(file, ec);
    std::cout << dump({{"status", skipped ? "error" : "ok"},
                       {"file", fromFile ? nlohmann::json(file.string()) : nlohmann::json(nullptr)},
                       {"tools", rows},
                       {"issues", issues}})
              << '\n';
    return skipped ? kExitError : kExitOk;
}

std::optional<Message> exportTools(controller::Controller& controller, const SimOptions& o) {
    if (!o.toolsOut) {
        return std::nullopt;
    }
    return files::writeOutputFile(*o.toolsOut, tools::formatToolTable(controller.toolTableEdits().table()));
}

} // namespace m350::sim
