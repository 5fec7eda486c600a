#pragma once

#include "core/params/ParameterTable.h"

#include <optional>
#include <span>
#include <string>

namespace m350::params {

// A function of the IO page: its parameter triple (N = pin, N+1 = enable, N+2 = active level),
// inputs in params 500-697 (pins IN01-IN24), outputs in 715-792 (pins OUT01-OUT21), and the M codes
// that use it.
struct IoFunction {
    int parameter = 0;
    bool input = true;
    const char* nameEn = "";
    const char* nameZh = "";
};

// Where a function is wired, read from the parameters.
struct PortAssignment {
    const IoFunction* function = nullptr;
    int pin = 0;           // 0: not assigned
    bool enabled = false;
    int activeLevel = 1;   // the level that means "on" / "active"

    bool wired() const { return enabled && pin > 0; }
};

std::span<const IoFunction> ioFunctions();
const IoFunction* ioFunction(int parameter);

PortAssignment portAssignment(const ParameterTable& parameters, int functionParameter);
// The input function's assignment when it is enabled on a pin IN01-IN24, else nothing.
std::optional<PortAssignment> wiredInput(const ParameterTable& parameters, int functionParameter);

// The enabled function wired to a pin (the first in parameter order when several share it).
std::optional<PortAssignment> inputOnPin(const ParameterTable& parameters, int pin);
std::optional<PortAssignment> outputOnPin(const ParameterTable& parameters, int pin);

// "IN11", "OUT01".
std::string inputName(int pin);
std::string outputName(int pin);
// "IN11 (tool released)" when a function is wired to the pin, else "IN11"; the function's Chinese
// name with `chinese`.
std::string describeInput(const ParameterTable& parameters, int pin, bool chinese = false);

} // namespace m350::params
