#include "core/config/ModbusSlaves.h"

#include "core/files/Toml.h"

#include <charconv>
#include <cmath>
#include <filesystem>

namespace m350::config {

namespace {

std::optional<int> numberKey(std::string_view key, int low, int high) {
    int n = 0;
    auto [ptr, ec] = std::from_chars(key.data(), key.data() + key.size(), n);
    if (ec != std::errc() || ptr != key.data() + key.size() || n < low || n > high) {
        return std::nullopt;
    }
    return n;
}

std::string lineOf(const toml::node& node) {
    return "line " + std::to_string(node.source().begin.line) + ": ";
}

} // namespace

std::optional<std::string> loadModbusSlaves(const std::string& path, ModbusSlaves& out) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) {
        return std::nullopt;
    }
    toml::table t;
    try {
        t = files::parseTomlFile(path);
    } catch (const toml::parse_error& e) {
        return std::to_string(e.source().begin.line) + ":" + std::to_string(e.source().begin.column) + ": " +
               std::string(e.description());
    }
    const toml::table* slaves = t["slave"].as_table();
    if (!slaves) {
        return t.contains("slave") ? std::optional<std::string>("'slave' must be a table: [slave.1.holding]")
                                   : std::nullopt;
    }
    for (auto&& [key, node] : *slaves) {
        auto slave = numberKey(key.str(), 1, 247);
        const toml::table* holding = node.as_table() ? (*node.as_table())["holding"].as_table() : nullptr;
        if (!slave || !holding) {
            return lineOf(node) + "[slave." + std::string(key.str()) +
                   "] must be a slave address 1-247 with a table of holding registers: [slave.1.holding]";
        }
        auto& registers = out.holding[*slave];
        for (auto&& [address, value] : *holding) {
            auto number = numberKey(address.str(), 0, 65535);
            auto v = value.value<double>();
            if (!number || !v || *v != std::floor(*v) || *v < -32768 || *v > 65535) {
                return lineOf(value) + "slave " + std::to_string(*slave) + " register '" + std::string(address.str()) +
                       "': addresses are 0-65535 and values whole numbers from -32768 to 65535";
            }
            registers[*number] = static_cast<std::uint16_t>(static_cast<int>(*v) & 0xFFFF);
        }
    }
    return std::nullopt;
}

} // namespace m350::config
