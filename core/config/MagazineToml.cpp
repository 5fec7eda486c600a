#include "core/config/MagazineToml.h"

#include "core/machine/MachineTypes.h"

#include <cmath>

namespace m350::config {

namespace {

using Device = MagazineConfig::Device;

struct Invalid {
    Message words;
};

// A whole pin number within 1..count (0 when absent).
int pin(const toml::table& t, const char* key, int count) {
    const toml::node* node = t.get(key);
    if (!node) {
        return 0;
    }
    auto n = node->value<int64_t>();
    if (!n || *n < 1 || *n > count) {
        throw Invalid{message("config_magazine_pin", {key, std::to_string(count)})};
    }
    return static_cast<int>(*n);
}

double positive(const toml::table& t, const char* key, double fallback) {
    double v = t[key].value_or(fallback);
    if (!(v >= 0.0)) {
        throw Invalid{message("config_magazine_negative", {key})};
    }
    return v;
}

std::string choice(const toml::table& t, const char* key, std::string fallback, std::initializer_list<const char*> allowed) {
    std::string v = t[key].value_or(fallback);
    std::string english;
    std::string chinese;
    for (const char* a : allowed) {
        if (v == a) {
            return v;
        }
        english += std::string(english.empty() ? "" : " or ") + "\"" + a + "\"";
        chinese += std::string(chinese.empty() ? "" : "或") + "\"" + a + "\"";
    }
    throw Invalid{message("config_magazine_choice", {key, bilingual(english, chinese), v})};
}

void readRack(const toml::table& t, MagazineConfig& out) {
    out.topLoading = choice(t, "loading", "side", {"side", "top"}) == "top";
    out.openingY = choice(t, "opening", "+Y", {"+Y", "-Y"}) == "+Y" ? 1.0 : -1.0;
    out.onGantry = choice(t, "carried", "fixed", {"fixed", "gantry"}) == "gantry";
    out.slideTravel = positive(t, "slide_travel", out.slideTravel);
    if (const toml::node* forks = t.get("forks")) {
        const toml::array* list = forks->as_array();
        if (!list) {
            throw Invalid{message("config_magazine_forks")};
        }
        for (const toml::node& fork : *list) {
            const toml::array* xyz = fork.as_array();
            std::array<double, 3> at{};
            for (std::size_t i = 0; xyz && xyz->size() == 3 && i < 3; ++i) {
                at[i] = xyz->get(i)->value<double>().value_or(NAN);
            }
            if (!xyz || xyz->size() != 3 || !std::isfinite(at[0]) || !std::isfinite(at[1]) || !std::isfinite(at[2])) {
                throw Invalid{message("config_magazine_forks")};
            }
            out.forks.push_back(at);
        }
        if (out.forks.size() > 20) {
            throw Invalid{message("config_magazine_forks_count")};
        }
    }
    if (out.onGantry && out.topLoading) {
        throw Invalid{message("config_magazine_gantry_side")};
    }
}

void readDisc(const toml::table& t, MagazineConfig& out) {
    if (const toml::array* select = t["select_outputs"].as_array()) {
        for (const toml::node& n : *select) {
            auto v = n.value<int64_t>();
            if (!v || *v < 1 || *v > machine::kOutputCount) {
                throw Invalid{message("config_magazine_select_outputs")};
            }
            out.selectOutputs.push_back(static_cast<int>(*v));
        }
    }
    out.strobeOutput = pin(t, "strobe_output", machine::kOutputCount);
    if (const toml::node* station = t.get("station")) {
        const toml::array* xyz = station->as_array();
        std::array<double, 3> at{};
        for (std::size_t i = 0; xyz && xyz->size() == 3 && i < 3; ++i) {
            at[i] = xyz->get(i)->value<double>().value_or(NAN);
        }
        if (!xyz || xyz->size() != 3 || !std::isfinite(at[0]) || !std::isfinite(at[1]) || !std::isfinite(at[2])) {
            throw Invalid{message("config_magazine_station")};
        }
        out.station = at;
    }
    if (out.selectOutputs.empty() || out.strobeOutput == 0 || out.inPositionInput == 0) {
        throw Invalid{message("config_magazine_disc_needs")};
    }
}

void readUmbrella(const toml::table& t, MagazineConfig& out) {
    out.pockets = t["pockets"].value_or(0);
    if (out.pockets < 1 || out.pockets > 99) {
        throw Invalid{message("config_magazine_umbrella_pockets")};
    }
    out.slideSeconds = positive(t, "slide_s", out.slideSeconds);
    out.slideOutput = pin(t, "slide_output", machine::kOutputCount);
    out.atSpindleInput = pin(t, "at_spindle_input", machine::kInputCount);
    out.awayInput = pin(t, "away_input", machine::kInputCount);
    out.drawbarOutput = pin(t, "drawbar_output", machine::kOutputCount);
    out.releasedInput = pin(t, "released_input", machine::kInputCount);
    out.clampedInput = pin(t, "clamped_input", machine::kInputCount);
    if (out.slideOutput == 0 || out.atSpindleInput == 0 || out.awayInput == 0 || out.inPositionInput == 0 ||
        out.drawbarOutput == 0 || out.releasedInput == 0 || out.clampedInput == 0) {
        throw Invalid{message("config_magazine_umbrella_needs")};
    }
    if (const toml::array* xy = t["change_xy"].as_array()) {
        if (xy->size() != 2 || !xy->get(0)->value<double>() || !xy->get(1)->value<double>()) {
            throw Invalid{message("config_magazine_change_xy")};
        }
        out.changeXYGiven = true;
        out.changeX = *xy->get(0)->value<double>();
        out.changeY = *xy->get(1)->value<double>();
    }
}

} // namespace

std::optional<Message> readMagazine(const toml::table& t, MagazineConfig& out) {
    try {
        std::string device = choice(t, "device", "", {"linear-rack", "servo-disc", "umbrella", "multi-head"});
        out.device = device == "linear-rack"  ? Device::LinearRack
                     : device == "servo-disc" ? Device::ServoDisc
                     : device == "umbrella"   ? Device::Umbrella
                                              : Device::MultiHead;
        out.forkDepth = positive(t, "fork_depth", out.forkDepth);
        out.tolerance = positive(t, "tolerance", out.tolerance);
        out.secondsPerPocket = positive(t, "seconds_per_pocket", out.secondsPerPocket);
        out.settleSeconds = positive(t, "settle_s", out.settleSeconds);
        out.clampSeconds = positive(t, "clamp_ms", 0.0) / 1000.0;
        out.inPositionInput = pin(t, "in_position_input", machine::kInputCount);
        switch (out.device) {
        case Device::LinearRack: readRack(t, out); break;
        case Device::ServoDisc: readDisc(t, out); break;
        case Device::Umbrella: readUmbrella(t, out); break;
        case Device::MultiHead:
        case Device::None: break;
        }
    } catch (const Invalid& invalid) {
        return invalid.words;
    }
    return std::nullopt;
}

} // namespace m350::config
