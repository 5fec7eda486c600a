#pragma once

#include "core/common/Message.h"
#include "core/params/ParameterTable.h"

#include <optional>
#include <string>
#include <unordered_map>
#include <variant>
#include <vector>

namespace m350::params {

struct ParameterOption {
    double value = 0;
    std::string zh, en;
};

// One row of the controller's parameter list: what the M350's parameter pages show for it.
struct ParameterInfo {
    int number = 0;
    int group = 0; // the parameter page; 0 = not shown on any page
    std::string groupZh, groupEn, nameZh, nameEn, unit;
    enum class Type { Int, Real, Select } type = Type::Real;
    double min = 0, max = 0;
    std::vector<ParameterOption> options; // Select only
    double defaultValue = 0;
    bool hidden = false;
};

// Names, ranges, options and factory defaults of the M350's parameters, read from
// resources/parameters/m350-parameters.tsv (see the README beside it). Some catalogued numbers
// (the CAM-teach forms, 1000 and up) lie beyond ParameterTable.
class ParameterCatalogue {
public:
    // The catalogue, or an error naming the file and line.
    static std::variant<ParameterCatalogue, std::string> load(const std::string& tsvPath);
    static std::string bundledPath();
    // The bundled catalogue (or why it cannot be read), read on its first use and shared after
    // that: a run, a machine folder and the panel's pages all ask for it.
    static const std::variant<ParameterCatalogue, std::string>& bundled();

    const ParameterInfo* find(int number) const;
    const std::vector<ParameterInfo>& all() const { return params_; } // in page order, as the TSV

    // nullopt when the controller would accept `value`; else the reason, by message id.
    std::optional<Message> validate(int number, double value) const;
    // `value` at the parameter's resolution, as params.toml keeps it: a whole number for an int or
    // a select, four decimals for a real (the pages show three; taught positions such as the
    // factory 135 = 5.7195 carry four); an uncatalogued number as it is.
    double atResolution(int number, double value) const;
    // Sets every catalogued parameter that ParameterTable holds to its default.
    void applyDefaults(ParameterTable& table) const;

private:
    std::vector<ParameterInfo> params_;
    std::unordered_map<int, std::size_t> index_;
};

} // namespace m350::params
