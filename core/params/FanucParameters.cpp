#include "core/params/FanucParameters.h"

#include <cmath>
#include <cstdio>

namespace m350::params {

namespace {

struct Simulated {
    int number;
    double low;
    double high;
    double defaultValue;
    bool whole = false; // a bit parameter's byte or a count
    int last = 0;       // a run of parameters number..last alike (0: the one number)
};

constexpr Simulated kSimulated[] = {
    // The article on spindle-load breakage detection: Load% = L / 32767 x lambda, lambda default 143.
    {kLoadMeterFullScale, 1.0, 1000.0, 143.0},
    // Tool life: 6800 and 6801 are bit parameters (0-255), 6810 the ignore number 0-9999; its default is
    // the 100 the 0i manual's examples assume (T101 = group 1).
    {kToolLifeSettings, 0.0, 255.0, 0.0, true},
    {kToolLifeExtended, 0.0, 255.0, 0.0, true},
    {kToolLifeIgnoreNumber, 0.0, 9999.0, 100.0, true},
    // Codes that call programs (CallCodeParameters.h); 0 calls nothing.
    {kFirstGCodeMacroCall, 0.0, 9999.0, 0.0, false, kFirstGCodeMacroCall + 9},
    {kFirstMCodeSubprogramCall, 0.0, 99999999.0, 0.0, false, kFirstMCodeSubprogramCall + 8},
    {kFirstMCodeMacroCall, 0.0, 99999999.0, 0.0, false, kFirstMCodeMacroCall + 9},
    {kFirstAddressCall, 0.0, 90.0, 0.0, false, kFirstAddressCall + 1},
};

const Simulated* find(int number) {
    for (const Simulated& p : kSimulated) {
        if (p.number == number || (number > p.number && number <= p.last)) {
            return &p;
        }
    }
    return nullptr;
}

} // namespace

bool isFanucParameterNumber(int number) {
    return number >= kFirstFanucParameter && number <= kLastFanucParameter;
}

std::optional<Message> refusedFanucParameter(int number, double value) {
    if (!std::isfinite(value)) {
        return message("fanuc_param_not_finite", {std::to_string(number)});
    }
    if (const Simulated* p = find(number); p && (value < p->low || value > p->high || (p->whole && value != std::floor(value)))) {
        char low[32];
        char high[32];
        std::snprintf(low, sizeof low, "%.10g", p->low);
        std::snprintf(high, sizeof high, "%.10g", p->high);
        return message(p->whole ? "fanuc_param_whole_range" : "fanuc_param_range", {std::to_string(number), low, high});
    }
    return std::nullopt;
}

std::optional<Message> unreadFanucParameter(int number) {
    if (find(number)) {
        return std::nullopt;
    }
    return message("fanuc_param_not_simulated", {std::to_string(number)});
}

double fanucParameter(const std::map<int, double>& values, int number) {
    if (auto it = values.find(number); it != values.end()) {
        return it->second;
    }
    const Simulated* p = find(number);
    return p ? p->defaultValue : 0.0;
}

} // namespace m350::params
