#include "core/config/ModbusSlaves.h"

#include "core/files/Toml.h"

#include <charconv>
#include <cmath>
#include <cstdint>
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
    return std::to_string(node.source().begin.line);
}

} // namespace

std::optional<Message> loadModbusSlaves(const std::string& path, ModbusSlaves& out) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) {
        return std::nullopt;
    }
    toml::table t;
    try {
        t = files::parseTomlFile(path);
    } catch (const files::UnreadableToml& e) {
        return message("folder_cannot_read", {std::to_string(e.source().begin.line) + ":" + std::to_string(e.source().begin.column),
                                             bilingual(e.reason())});
    } catch (const toml::parse_error& e) {
        return message("modbus_toml_syntax",
                       {std::to_string(e.source().begin.line) + ":" + std::to_string(e.source().begin.column),
                        std::string(e.description())});
    }
    const toml::table* slaves = t["slave"].as_table();
    if (!slaves) {
        return t.contains("slave") ? std::optional<Message>(message("modbus_slave_table")) : std::nullopt;
    }
    for (auto&& [key, node] : *slaves) {
        auto slave = numberKey(key.str(), 1, 247);
        const toml::table* tables = node.as_table();
        if (!slave || !tables) {
            return message("modbus_slave_address", {lineOf(node), std::string(key.str())});
        }
        devices::ModbusMemory& memory = out.slaves[*slave];
        for (auto&& [kind, entries] : *tables) {
            const std::string name(kind.str());
            const bool registers = name == "holding" || name == "input";
            const bool bits = name == "coils" || name == "discrete";
            const toml::table* table = entries.as_table();
            if ((!registers && !bits) || !table) {
                return message("modbus_unknown_table", {lineOf(entries), std::to_string(*slave), name});
            }
            for (auto&& [address, value] : *table) {
                auto number = numberKey(address.str(), 0, 65535);
                const std::vector<std::string> where{lineOf(value), std::to_string(*slave), name,
                                                     std::string(address.str())};
                if (registers) {
                    auto v = value.value<double>();
                    if (!number || !v || *v != std::floor(*v) || *v < -32768 || *v > 65535) {
                        return message("modbus_register_value", where);
                    }
                    auto& target = name == "holding" ? memory.holding : memory.input;
                    target[*number] = static_cast<std::uint16_t>(static_cast<int>(*v) & 0xFFFF);
                    continue;
                }
                std::optional<bool> on;
                if (auto b = value.value_exact<bool>()) {
                    on = *b;
                } else if (auto i = value.value_exact<std::int64_t>(); i && (*i == 0 || *i == 1)) {
                    on = *i == 1;
                }
                if (!number || !on) {
                    return message("modbus_bit_value", where);
                }
                (name == "coils" ? memory.coils : memory.discrete)[*number] = *on;
            }
        }
    }
    return std::nullopt;
}

} // namespace m350::config
