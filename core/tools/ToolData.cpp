#include "core/tools/ToolData.h"

#include "core/common/Numeric.h"
#include "core/params/ParameterNumbers.h"
#include "core/tools/ToolTableFile.h"

#include <algorithm>
#include <cmath>
#include <variant>

namespace m350::tools {


std::optional<int> m350ZParameter(int tool, const params::ParameterTable& parameters) {
    const int capacity = saturatingInt(parameters.get(param::kMagazineCapacity));
    if (tool >= 1 && tool <= capacity && tool <= param::kToolZOffsetCount) {
        return param::kToolZOffsetFirst + tool - 1;
    }
    const int virtualIndex = tool - capacity;
    if (tool > capacity && virtualIndex >= 1 && virtualIndex <= param::kVirtualToolZOffsetCount) {
        return param::kVirtualToolZOffsetFirst + virtualIndex - 1;
    }
    return std::nullopt;
}

double roundedOffset(double value) { return std::round(value * 1e6) / 1e6; }

ToolData::ToolData(const gcode::Dialect& dialect, params::ParameterTable& parameters, std::optional<ToolTable> loaded)
    : dialect_(&dialect), parameters_(&parameters) {
    if (loaded) {
        rows_ = std::move(*loaded);
        for (const ToolEntry& entry : rows_.entries()) {
            if (auto p = zParameter(entry.tool); p && entry.offsets[kZ]) {
                parameters_->set(*p, *entry.offsets[kZ]);
            }
        }
        return;
    }
    if (m350()) {
        const int capacity = std::min(saturatingInt(parameters.get(param::kMagazineCapacity)), param::kToolZOffsetCount);
        for (int tool = 1; tool <= capacity; ++tool) {
            ToolEntry entry;
            entry.tool = tool;
            entry.pocket = tool;
            entry.offsets[kZ] = parameters.get(param::kToolZOffsetFirst + tool - 1);
            rows_.put(entry);
        }
    }
}

std::optional<int> ToolData::zParameter(int tool) const {
    return m350() ? m350ZParameter(tool, *parameters_) : std::nullopt;
}

std::vector<int> ToolData::toolsWithZParameters() const {
    std::vector<int> tools;
    if (!m350()) {
        return tools;
    }
    const int capacity = saturatingInt(parameters_->get(param::kMagazineCapacity));
    for (int tool = 1; tool <= std::min(capacity, param::kToolZOffsetCount); ++tool) {
        tools.push_back(tool);
    }
    for (int index = 1; index <= param::kVirtualToolZOffsetCount; ++index) {
        tools.push_back(std::max(capacity, 0) + index);
    }
    return tools;
}

ToolTable ToolData::table() const {
    ToolTable out = rows_;
    if (!m350()) {
        return out;
    }
    for (int tool : toolsWithZParameters()) {
        const double value = parameters_->get(*zParameter(tool));
        if (const ToolEntry* row = out.find(tool)) {
            if (row->offsets[kZ] || value != 0.0) {
                ToolEntry entry = *row;
                entry.offsets[kZ] = value;
                out.put(entry); // keeps the row's text when the value is the one it was read with
            }
        } else if (value != 0.0) {
            if (std::optional<int> pocket = out.freePocket(tool)) {
                ToolEntry entry;
                entry.tool = tool;
                entry.pocket = *pocket;
                entry.offsets[kZ] = value;
                out.put(entry);
            }
        }
    }
    return out;
}

std::optional<ToolEntry> ToolData::find(int tool) const {
    const ToolEntry* row = rows_.find(tool);
    std::optional<int> p = zParameter(tool);
    if (!p) {
        return row ? std::optional<ToolEntry>(*row) : std::nullopt;
    }
    ToolTable whole = table();
    const ToolEntry* found = whole.find(tool);
    return found ? std::optional<ToolEntry>(*found) : std::nullopt;
}

std::optional<Message> ToolData::put(const ToolEntry& entry) {
    if (auto why = rows_.put(entry)) {
        return why;
    }
    changedSinceLoad_.insert(entry.tool);
    if (auto p = zParameter(entry.tool)) {
        parameters_->set(*p, entry.offset(kZ));
    }
    ++revision_;
    return std::nullopt;
}

bool ToolData::remove(int tool) {
    if (!rows_.remove(tool)) {
        return false;
    }
    if (auto p = zParameter(tool)) {
        parameters_->set(*p, 0.0);
    }
    ++revision_;
    return true;
}

void ToolData::replace(const ToolTable& table) {
    if (table == this->table()) {
        return;
    }
    rows_ = table;
    for (int tool : toolsWithZParameters()) {
        const ToolEntry* row = rows_.find(tool);
        parameters_->set(*zParameter(tool), row ? row->offset(kZ) : 0.0);
    }
    ++revision_;
}

double ToolData::z(int tool) const {
    if (auto p = zParameter(tool)) {
        return parameters_->get(*p);
    }
    const ToolEntry* row = rows_.find(tool);
    return row ? row->offset(kZ) : 0.0;
}

std::optional<double> ToolData::diameter(int tool) const {
    const ToolEntry* row = rows_.find(tool);
    return row ? row->diameter : std::nullopt;
}

std::optional<Message> ToolData::setZ(int tool, double value) {
    ToolEntry entry;
    if (const ToolEntry* row = rows_.find(tool)) {
        entry = *row;
    } else {
        std::optional<int> pocket = rows_.freePocket(tool);
        if (!pocket) {
            return message("tool_table_full_tool", {std::to_string(ToolTable::kMaxTools), std::to_string(tool)});
        }
        entry.tool = tool;
        entry.pocket = *pocket;
    }
    entry.offsets[kZ] = value;
    return put(entry);
}

std::string_view offsetRegisterName(OffsetRegister r) {
    switch (r) {
    case OffsetRegister::LengthGeometry: return "H geometry";
    case OffsetRegister::LengthWear: return "H wear";
    case OffsetRegister::RadiusGeometry: return "D geometry";
    case OffsetRegister::RadiusWear: return "D wear";
    }
    return "H geometry";
}

double ToolData::lengthOffset(int number) const {
    if (memory_ == OffsetMemory::A) {
        return z(number);
    }
    return registerValue(OffsetRegister::LengthGeometry, number) + registerValue(OffsetRegister::LengthWear, number);
}

double ToolData::radiusOffset(int number) const {
    const ToolEntry* row = rows_.find(number);
    if (!row) {
        return 0.0;
    }
    if (memory_ == OffsetMemory::A) {
        return row->diameter ? *row->diameter / 2.0 : row->offset(kZ);
    }
    return row->diameter.value_or(0.0) / 2.0 + row->radiusWear.value_or(0.0);
}

double ToolData::registerValue(OffsetRegister r, int number) const {
    if (r == OffsetRegister::LengthGeometry) {
        return z(number);
    }
    const ToolEntry* row = rows_.find(number);
    if (!row) {
        return 0.0;
    }
    switch (r) {
    case OffsetRegister::LengthWear: return row->lengthWear.value_or(0.0);
    case OffsetRegister::RadiusGeometry: return row->diameter.value_or(0.0) / 2.0;
    default: return row->radiusWear.value_or(0.0);
    }
}

std::optional<Message> ToolData::setRegister(OffsetRegister r, int number, double value) {
    const ToolEntry* row = rows_.find(number);
    if (!row && value == 0.0) {
        return std::nullopt; // an offset that is 0 needs no row
    }
    if (r == OffsetRegister::LengthGeometry) {
        return setZ(number, value);
    }
    ToolEntry entry;
    if (row) {
        entry = *row;
    } else {
        std::optional<int> pocket = rows_.freePocket(number);
        if (!pocket) {
            return message("tool_table_full_offset", {std::to_string(ToolTable::kMaxTools), std::to_string(number)});
        }
        entry.tool = number;
        entry.pocket = *pocket;
    }
    switch (r) {
    case OffsetRegister::LengthWear: entry.lengthWear = value; break;
    case OffsetRegister::RadiusGeometry: entry.diameter = 2.0 * value; break;
    default: entry.radiusWear = value; break;
    }
    return put(entry);
}

std::pair<OffsetRegister, int> ToolData::variableRegister(int index) const {
    if (memory_ == OffsetMemory::A) {
        return {OffsetRegister::LengthGeometry, index};
    }
    return index <= kMemoryCOffsets ? std::pair{OffsetRegister::LengthWear, index}
                                    : std::pair{OffsetRegister::LengthGeometry, index - kMemoryCOffsets};
}

double ToolData::offsetVariable(int index) const {
    auto [r, number] = variableRegister(index);
    return registerValue(r, number);
}

std::optional<Message> ToolData::setOffsetVariable(int index, double value) {
    auto [r, number] = variableRegister(index);
    return setRegister(r, number, value);
}

std::optional<Message> ToolData::reload(std::vector<std::string>& skipped) {
    auto read = readToolTableFile(sourceFile_);
    if (auto* error = std::get_if<Message>(&read)) {
        return *error;
    }
    ParsedToolTable& parsed = std::get<ParsedToolTable>(read);
    for (const ToolTableIssue& issue : parsed.issues) {
        skipped.push_back(bilingual(formatIssue(issue), formatIssue(issue, MessageLanguage::Chinese)));
    }
    ToolTable table = std::move(parsed.table);
    for (int tool : changedSinceLoad_) {
        if (const ToolEntry* mine = rows_.find(tool)) {
            if (const ToolEntry* other = table.findPocket(mine->pocket); other && other->tool != tool) {
                continue; // the file moved another tool into its pocket: the file's word stands
            }
            table.put(*mine);
        }
    }
    const std::set<int> kept = changedSinceLoad_;
    replace(table);
    changedSinceLoad_ = kept;
    return std::nullopt;
}

bool ToolData::setPocket(int tool, int pocket) {
    const ToolEntry* row = rows_.find(tool);
    if (!row) {
        return false;
    }
    ToolEntry entry = *row;
    entry.pocket = pocket;
    return !put(entry);
}

void ToolData::swapPockets(int from, int to) {
    const ToolEntry* incoming = rows_.find(to);
    if (from == to || !incoming) {
        return;
    }
    const int freed = incoming->pocket;
    const std::optional<int> aside = rows_.freePocket(ToolTable::kMaxPocket);
    if (!aside || !setPocket(to, *aside)) {
        return;
    }
    if (rows_.find(from)) {
        setPocket(from, freed);
    }
    setPocket(to, 0);
}

ToolData::Mark ToolData::mark() const {
    Mark out;
    out.revision = revision_;
    for (int i = 0; i < param::kToolZOffsetCount; ++i) {
        out.zParameters[static_cast<std::size_t>(i)] = parameters_->get(param::kToolZOffsetFirst + i);
    }
    for (int i = 0; i < param::kVirtualToolZOffsetCount; ++i) {
        out.zParameters[static_cast<std::size_t>(param::kToolZOffsetCount + i)] =
            parameters_->get(param::kVirtualToolZOffsetFirst + i);
    }
    return out;
}

} // namespace m350::tools
