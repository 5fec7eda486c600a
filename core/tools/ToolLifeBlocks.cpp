#include "core/tools/ToolLifeBlocks.h"

#include "core/common/Numeric.h"
#include "core/macro/MacroError.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace m350::tools {

namespace {

using macro::MacroError;
using macro::WordValue;

bool isCode(const WordValue& w, char letter, int number) {
    return w.letter == letter && std::abs(w.value - number) < 1e-9;
}

const WordValue* find(const std::vector<WordValue>& words, char letter) {
    auto it = std::find_if(words.begin(), words.end(), [letter](const WordValue& w) { return w.letter == letter; });
    return it == words.end() ? nullptr : &*it;
}

int wholeValue(const WordValue& w) {
    if (std::abs(w.value - std::round(w.value)) > 1e-9) {
        throw MacroError::of(AlarmCode::InvalidWord, message("tool_life_whole", {std::string(1, w.letter)}), w.column);
    }
    return roundToInt(w.value);
}

void check(const std::optional<Message>& problem, std::uint32_t column) {
    if (problem) {
        throw MacroError::of(AlarmCode::InvalidWord, *problem, column);
    }
}

// One block inside G10 L3 .. G11.
[[gnu::noinline]] void entryBlock(ToolLifeManager& manager, const std::vector<WordValue>& words) {
    std::uint32_t column = words.empty() ? 0 : words.front().column;
    if (std::any_of(words.begin(), words.end(), [](const WordValue& w) { return isCode(w, 'G', 11); })) {
        auto g11OrN = [](const WordValue& w) { return w.letter == 'N' || isCode(w, 'G', 11); };
        if (!std::all_of(words.begin(), words.end(), g11OrN) ||
            std::count_if(words.begin(), words.end(), [](const WordValue& w) { return w.letter == 'G'; }) != 1) {
            throw MacroError::of(AlarmCode::InvalidWord, message("tool_life_g11_alone"), column);
        }
        check(manager.endEntry(), column);
        return;
    }
    ToolLifeManager::EntryLine line;
    for (const WordValue& w : words) {
        std::optional<int>* slot = nullptr;
        switch (w.letter) {
        case 'P': slot = &line.p; break;
        case 'L': slot = &line.l; break;
        case 'Q': slot = &line.q; break;
        case 'T': slot = &line.t; break;
        case 'H': slot = &line.h; break;
        case 'D': slot = &line.d; break;
        case 'N': continue;
        default:
            throw MacroError::of(AlarmCode::InvalidWord, message("tool_life_entry_word", {std::string(1, w.letter)}),
                                 w.column);
        }
        *slot = wholeValue(w);
    }
    check(manager.entryLine(line), column);
}

// A block with a word tool life acts on (T H D G10 G11 M06), outside G10 L3 data entry.
[[gnu::noinline]] bool applyToRelevantBlock(ToolLifeManager& manager, std::vector<WordValue>& words,
                                            const ToolLifeBlockContext& context) {
    const WordValue* g10 = nullptr;
    for (const WordValue& w : words) {
        if (isCode(w, 'G', 10)) {
            g10 = &w;
        } else if (isCode(w, 'G', 11)) {
            throw MacroError::of(AlarmCode::InvalidWord, message("tool_life_g11_without_g10"), w.column);
        }
    }
    if (const WordValue* l = find(words, 'L'); g10 && l && isCode(*l, 'L', 3)) {
        const WordValue* p = find(words, 'P');
        auto counted = std::count_if(words.begin(), words.end(), [](const WordValue& w) { return w.letter != 'N'; });
        if (counted != (p ? 3 : 2)) {
            throw MacroError::of(AlarmCode::InvalidWord, message("tool_life_g10_alone"), g10->column);
        }
        check(manager.beginEntry(p ? wholeValue(*p) : 0), g10->column);
        return true;
    }
    if (!manager.enabled()) {
        return false;
    }
    for (WordValue& w : words) {
        if (w.letter == 'T') {
            int t = wholeValue(w);
            if (!manager.isGroupCommand(t)) {
                manager.selectOrdinaryTool();
            } else {
                ToolLifeManager::Selection chosen = manager.selectGroup(t);
                if (chosen.refusal) {
                    throw MacroError::of(AlarmCode::InvalidWord, *chosen.refusal, w.column);
                }
                w.value = chosen.tool;
            }
            if (context.tChangesTool) {
                manager.changeTool(!context.scanning);
            }
        }
    }
    for (WordValue& w : words) {
        if ((w.letter == 'H' || w.letter == 'D') && isCode(w, w.letter, 99)) {
            auto offset = manager.offsetOfToolInUse(w.letter);
            if (auto* why = std::get_if<Message>(&offset)) {
                throw MacroError::of(AlarmCode::InvalidWord, *why, w.column);
            }
            w.value = std::get<int>(offset);
        }
    }
    if (!context.tChangesTool && std::any_of(words.begin(), words.end(), [](const WordValue& w) { return isCode(w, 'M', 6); })) {
        manager.changeTool(!context.scanning);
    }
    return false;
}

bool actsOn(const WordValue& w) {
    switch (w.letter) {
    case 'T': case 'H': case 'D': return true;
    case 'G': return isCode(w, 'G', 10) || isCode(w, 'G', 11);
    case 'M': return isCode(w, 'M', 6);
    default: return false;
    }
}

} // namespace

// Most blocks have nothing for tool life: the executor's side asks mayConcernToolLife() first, and
// the work is kept out of line (noinline).
bool applyToolLife(ToolLifeManager& manager, macro::EvaluatedBlock& block, const ToolLifeBlockContext& context) {
    if (manager.entering()) [[unlikely]] {
        entryBlock(manager, block.words);
        return true;
    }
    if (mayConcernToolLife(manager, block) && std::any_of(block.words.begin(), block.words.end(), actsOn)) [[unlikely]] {
        return applyToRelevantBlock(manager, block.words, context);
    }
    return false;
}

} // namespace m350::tools
