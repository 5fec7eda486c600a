#include "core/config/SpindleLoadToml.h"

#include "core/config/TomlReading.h"

#include <cstdio>

namespace m350::config {

namespace {

using toml_reading::fail;

// The number at `key` within low..high, if there.
void readNumber(const std::filesystem::path& file, const toml::table& table, const char* section, const char* key,
                double low, double high, double& out) {
    const toml::node* node = table.get(key);
    if (!node) {
        return;
    }
    double v = toml_reading::numberValue(file, *node, key);
    if (v < low || v > high) {
        char from[32];
        char to[32];
        std::snprintf(from, sizeof from, "%g", low);
        std::snprintf(to, sizeof to, "%g", high);
        fail(file, message("config_number_in_range", {section, key, from, to}), node->source());
    }
    out = v;
}

void readRange(const std::filesystem::path& file, const toml::table& stock, const char* key, double& low,
               double& high) {
    const toml::node* node = stock.get(key);
    if (!node) {
        return;
    }
    const toml::array* range = node->as_array();
    if (!range || range->size() != 2) {
        fail(file, message("config_stock_min_max", {key}), node->source());
    }
    low = toml_reading::numberValue(file, *range->get(0), key);
    high = toml_reading::numberValue(file, *range->get(1), key);
    if (low > high) {
        fail(file, message("config_stock_min_le_max", {key}), node->source());
    }
}

} // namespace

void readSpindleLoadWorld(const std::filesystem::path& file, const toml::table& machine,
                          std::optional<machine::SpindleLoadModel>& out) {
    const toml::table* stock = machine["stock"].as_table();
    const toml::table* load = machine["spindle_load"].as_table();
    if (!stock && !load) {
        return;
    }
    machine::SpindleLoadModel model;
    if (load) {
        double spikeMs = model.spikeSeconds * 1000.0;
        if (const toml::node* lambda = load->get("lambda")) {
            fail(file, message("config_lambda_parameter"), lambda->source());
        }
        readNumber(file, *load, "spindle_load", "idle", 0.0, 100.0, model.idle);
        readNumber(file, *load, "spindle_load", "per_krpm", 0.0, 100.0, model.perKrpm);
        readNumber(file, *load, "spindle_load", "per_cm3", 0.0, 100.0, model.perCm3);
        readNumber(file, *load, "spindle_load", "spike_factor", 1.0, 100.0, model.spikeFactor);
        readNumber(file, *load, "spindle_load", "spike_ms", 0.0, 10000.0, spikeMs);
        model.spikeSeconds = spikeMs / 1000.0;
    }
    if (stock) {
        machine::Stock s;
        if (!stock->contains("top")) {
            fail(file, message("config_stock_needs_top"), stock->source());
        }
        constexpr double kFar = 1e6;
        readNumber(file, *stock, "stock", "top", -kFar, kFar, s.top);
        readRange(file, *stock, "x", s.xMin, s.xMax);
        readRange(file, *stock, "y", s.yMin, s.yMax);
        model.stock = s;
    }
    out = model;
}

} // namespace m350::config
