#include "core/config/ParamsToml.h"

#include "core/config/CallCodeParameters.h"
#include "core/config/MachineFolder.h"
#include "core/config/TomlReading.h"
#include "core/params/FanucParameters.h"
#include "core/params/ParameterCatalogue.h"
#include "core/params/ParameterLimits.h"

#include <string>
#include <variant>

namespace m350::config {

namespace fs = std::filesystem;

namespace {

using namespace toml_reading;

} // namespace

void loadParams(const fs::path& folder, MachineConfig& config) {
    fs::path file = folder / MachineFolder::fileName(FolderFile::Params);
    const auto* known = std::get_if<params::ParameterCatalogue>(&params::ParameterCatalogue::bundled());
    // On an M350 a parameter params.toml does not set has its factory value (the catalogue's
    // default, the firmware's default_setting), as after 恢复出厂设置; the uncatalogued ones (IO
    // enables and levels) stay 0. A FANUC control has none of the M350's factory values: there an
    // absent one stays 0, as before.
    if (known && config.dialect->id != gcode::DialectId::Fanuc) {
        known->applyDefaults(config.parameters);
    }
    if (!fs::exists(file)) {
        rebuildCallCodes(config); // [codes] alone: nothing to clash with
        return;
    }
    toml::table t = parseToml(file);
    warnUnknownKeys(file, t, {"params", "params.*"}, config);
    if (auto params = t["params"].as_table()) {
        for (auto&& [key, value] : *params) {
            const bool fanuc = config.dialect->id == gcode::DialectId::Fanuc;
            int n = numberKey(file, key.str(), key.source(), 0,
                              fanuc ? params::kLastFanucParameter : params::ParameterTable::kCount - 1,
                              bilingual("parameter", "参数"));
            double v = numberValue(file, value, key.str());
            if (params::isFanucParameterNumber(n)) {
                if (auto refused = params::refusedFanucParameter(n, v)) {
                    fail(file, *refused, value.source());
                }
                if (auto unread = params::unreadFanucParameter(n)) {
                    config.warn(warningAt(file, value.source(), *unread));
                }
                config.fanucParameters[n] = v;
                config.fanucParameterOrigins[n] = settingPlace(file, value.source());
                continue;
            }
            if (auto refused = params::refusedParameterValue(n, v)) {
                fail(file, *refused, value.source());
            }
            // A value the panel would refuse is kept (a simulator may be asked for it) but said; the
            // other members of the IO triples (enable, level) are not catalogued and pass as written.
            if (known && known->find(n)) {
                if (auto problem = known->validate(n, v)) {
                    const Message kept = message("param_kept_as_written", {file.string(), bilingual(*problem)});
                    config.warn(kept);
                }
            }
            config.parameters.set(n, v);
        }
    }
    if (auto refused = rebuildCallCodes(config)) {
        const toml::node* setting = t["params"].as_table()->get(std::to_string(refused->parameter));
        fail(file, refused->message, setting ? setting->source() : toml::source_region{});
    }
}

} // namespace m350::config
