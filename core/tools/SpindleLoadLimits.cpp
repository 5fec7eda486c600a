#include "core/tools/SpindleLoadLimits.h"

#include "core/files/Toml.h"

#include <charconv>
#include <cmath>
#include <filesystem>

namespace m350::tools {

namespace {

LoadSettingsError at(const toml::node& node, Message message) {
    return {static_cast<int>(node.source().begin.line), static_cast<int>(node.source().begin.column), std::move(message)};
}

std::optional<double> number(const toml::node* node) {
    if (!node) {
        return std::nullopt;
    }
    auto v = node->value<double>();
    return v && std::isfinite(*v) ? v : std::nullopt;
}

} // namespace

std::optional<LoadSettingsError> readLoadMonitorSettings(const std::string& path, LoadMonitorSettings& out) {
    if (!std::filesystem::exists(path)) {
        return std::nullopt;
    }
    toml::table t;
    try {
        t = files::parseTomlFile(path);
    } catch (const files::UnreadableToml& e) {
        return LoadSettingsError{static_cast<int>(e.source().begin.line), static_cast<int>(e.source().begin.column), e.why()};
    } catch (const toml::parse_error& e) {
        return LoadSettingsError{static_cast<int>(e.source().begin.line), static_cast<int>(e.source().begin.column),
                                 message("config_toml_syntax", {std::string(e.description())})};
    }
    if (const toml::table* monitor = t["monitor"].as_table()) {
        if (const toml::node* ms = monitor->get("sample_ms")) {
            auto v = number(ms);
            if (!v || *v < 1.0 || *v > 10000.0) {
                return at(*ms, message("spindle_load_sample_ms"));
            }
            out.sampleSeconds = *v / 1000.0;
        }
        if (const toml::node* n = monitor->get("samples")) {
            auto v = n->value<std::int64_t>();
            if (!v || *v < 1 || *v > 1000) {
                return at(*n, message("spindle_load_samples"));
            }
            out.samples = static_cast<int>(*v);
        }
    }
    if (const toml::table* tools = t["tool"].as_table()) {
        for (auto&& [key, value] : *tools) {
            int tool = 0;
            std::string_view k = key.str();
            auto [end, ec] = std::from_chars(k.data(), k.data() + k.size(), tool);
            const toml::table* limits = value.as_table();
            if (ec != std::errc() || end != k.data() + k.size() || tool < 1 || tool > 9999 || !limits) {
                return at(value, message("spindle_load_tool_key", {std::string(k)}));
            }
            LoadLimits l;
            auto lower = number(limits->get("lower"));
            auto upper = number(limits->get("upper"));
            if ((limits->contains("lower") && !lower) || (limits->contains("upper") && !upper)) {
                return at(value, message("spindle_load_not_numbers", {std::to_string(tool)}));
            }
            l.lower = lower.value_or(0.0);
            l.upper = upper.value_or(0.0);
            if (l.lower < 0.0 || l.upper < 0.0 || (l.upper > 0.0 && l.upper <= l.lower)) {
                return at(value, message("spindle_load_order", {std::to_string(tool)}));
            }
            out.tools[tool] = l;
        }
    }
    return std::nullopt;
}

} // namespace m350::tools
