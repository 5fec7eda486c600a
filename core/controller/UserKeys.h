#pragma once

#include "core/config/HookFiles.h"
#include "core/controller/KeyPress.h"
#include "core/gcode/Diagnostic.h"

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace m350::params {
class ParameterTable;
}

namespace m350::controller {

// The keys an M350 owner assigns: the panel's K1-K7 (params 210-216) and the external keys 1-6
// (params 272-277): 0 loads key-N.nc / extnc<N-1>-1.nc (start() then runs it), 1-21 switches that
// output over, above 1000 is the code of the panel key it stands for, which the panel presses.
// FUNC K01-K14 of the add-on keypad: #1996 = 249 + key, then ext_button.nc (`M#1996`), or that M
// code as MDI.
class UserKeys {
public:
    // What the keys load and switch through the controller that owns them; all of it outlives them.
    struct Context {
        const params::ParameterTable& parameters;
        std::function<int(int)> output;                // an output's level
        std::function<bool(int, int)> switchOutput;    // the IO page's switch (false while a program runs)
        std::function<bool(config::Hook)> loadHook;    // false: diagnostics() says why
        std::function<bool(config::Hook, const std::map<int, double>&, const std::vector<std::string>&)> loadHookOrMdi;
        std::function<const std::vector<gcode::Diagnostic>&()> diagnostics;
        std::function<void(std::string)> refuseLoad;  // nothing is loaded; the diagnostics say why
    };

    explicit UserKeys(Context context) : context_(std::move(context)) {}

    KeyPress pressUserKey(int key);
    KeyPress pressExternKey(int key);
    bool loadFunctionKey(int key);

private:
    KeyPress pressKey(int function, config::Hook hook, const std::string& key);

    Context context_;
};

} // namespace m350::controller
