// The message table (translations/messages.tsv): every message the core raises by id has English
// and Chinese with the same arguments, and every id the core's sources raise is in it.
#include "core/common/Alarm.h"
#include "core/common/Message.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace m350 {
namespace {

std::multiset<std::string> placeholders(const std::string& pattern) {
    std::multiset<std::string> found;
    for (std::size_t i = 0; i + 1 < pattern.size(); ++i) {
        if (pattern[i] == '%' && pattern[i + 1] >= '1' && pattern[i + 1] <= '9') {
            found.insert(pattern.substr(i, 2));
        }
    }
    return found;
}

// A CJK ideograph in UTF-8: U+4E00..U+9FFF is E4 B8 80 .. E9 BF BF.
bool hasChinese(const std::string& text) {
    for (std::size_t i = 0; i + 2 < text.size(); ++i) {
        const auto lead = static_cast<unsigned char>(text[i]);
        if (lead >= 0xE4 && lead <= 0xE9) {
            return true;
        }
    }
    return false;
}

// The Latin words a Chinese text may keep: G/M codes, macro statements, parameter and signal names,
// the machine folder's files and keys (machine.toml [variables] common), written as the operator
// types them.
bool hasEnglishWords(const std::string& text) {
    static const std::regex word("[A-Za-z]{4,}");
    static const std::set<std::string> kept{
        "MGETDATA", "MSETDATA", "Modbus", "modbus", "toml", "slave", "TLCH", "GOTO", "GOTOn", "THEN", "WHILE",
        "BPRNT", "DPRNT", "POPEN", "PCLOS", "FANUC", "ATAN", "FIFO", "LinuxCNC", "slib", "tool", "table", "machine", "variables", "common", "coordinates", "additional",
        "systems", "reference", "points", "params", "help",
        // the words of toollife.txt and tool.tbl lines, which the file keeps in any language
        "count", "minutes", "group", "life", "used", "ignore", "teeth", "type", "flat",
        // exercise.toml's keys and values, typed as the file has them
        "hints", "exercises", "time", "limit", "true", "false", "stuck", "slow", "bouncing", "pressed", "none", "begin", "start", "mdi",
        // machine.toml's sections, keys and values, as the file spells them
        "TOML", "away", "change", "changer", "clamped", "codes", "commanded", "data", "dialect", "distance", "drawbar",
        "empty", "false", "true", "fanuc", "homing", "input", "output", "outputs", "interface", "signal", "signals",
        "lambda", "libraries", "links", "load", "magazine", "memory", "name", "offset", "pockets", "position",
        "random", "released", "rotation", "select", "slide", "spindle", "stock", "strobe", "switch",
        // the command lines' options, the controller backup's file names
        "screenshot", "setting", "training", "replay", "exercise", "attempts", "review",
        // passwords.toml's levels and its "SALT:HASH"
        "operator", "admin", "super", "SALT", "HASH",
        // modbus.toml's tables
        "holding", "coils", "discrete", "forks", "station",
        // spindle-load.toml's keys
        "sample", "samples", "lower", "upper",
        // a save's NAME.pending file
        "pending",
        // params-backup.toml's table and key
        "backup", "format"};
    for (auto it = std::sregex_iterator(text.begin(), text.end(), word); it != std::sregex_iterator(); ++it) {
        if (kept.count(it->str()) == 0) {
            return true;
        }
    }
    return false;
}

TEST(MessageTable, EveryIdHasChineseWithTheSameArguments) {
    ASSERT_GT(messagePatterns().size(), 40u);
    std::set<std::string> ids;
    for (const MessagePattern& p : messagePatterns()) {
        SCOPED_TRACE(p.id);
        EXPECT_TRUE(ids.insert(p.id).second) << "twice in the table";
        EXPECT_TRUE(std::regex_match(p.id, std::regex("[a-z0-9_]+")));
        EXPECT_FALSE(p.english.empty());
        EXPECT_TRUE(hasChinese(p.chinese)) << p.chinese;
        EXPECT_NE(p.chinese, p.english);
        EXPECT_FALSE(hasEnglishWords(p.chinese)) << p.chinese;
        const std::multiset<std::string> chinese = placeholders(p.chinese);
        const std::multiset<std::string> english = placeholders(p.english);
        EXPECT_EQ(std::set<std::string>(chinese.begin(), chinese.end()),
                  std::set<std::string>(english.begin(), english.end()));
    }
}

TEST(MessageTable, EveryIdTheCoreRaisesIsInTheTable) {
    // message("id", ...) and ternaries of two ids: every quoted id after message( in core/
    const std::regex call(R"re(message\(\s*(?:[^"();]*\?\s*)?"([a-z0-9_]+)"(?:\s*:\s*"([a-z0-9_]+)")?)re");
    int found = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(M350_CORE_SOURCE_DIR)) {
        if (entry.path().extension() != ".cpp") {
            continue;
        }
        std::ifstream in(entry.path());
        std::stringstream text;
        text << in.rdbuf();
        const std::string source = text.str();
        for (auto it = std::sregex_iterator(source.begin(), source.end(), call); it != std::sregex_iterator(); ++it) {
            for (int group = 1; group <= 2; ++group) {
                if ((*it)[group].matched) {
                    ++found;
                    EXPECT_NE(findMessagePattern((*it)[group].str()), nullptr)
                        << entry.path().filename().string() << " raises " << (*it)[group].str();
                }
            }
        }
    }
    EXPECT_GT(found, 40);
}

TEST(MessageTable, SaysAMessageInEitherLanguageWithItsArguments) {
    const Message drop = message("rack_dropped", {"1", "X300.000 Y200.000 Z-10.000"});
    EXPECT_EQ(drop.english(), "T1 dropped: the drawbar was released at X300.000 Y200.000 Z-10.000 with no pocket under "
                              "the tool (it fell onto the table)");
    EXPECT_EQ(drop.in(MessageLanguage::Chinese), "T1掉落：在X300.000 Y200.000 Z-10.000松刀时刀具下方没有刀位（刀具掉到工作台上）");
    const Alarm alarm = Alarm::of(AlarmCode::Crash, drop, "prog.nc", 4, 2);
    EXPECT_EQ(alarm.message, drop.english());
    EXPECT_EQ(alarm.messageId, "rack_dropped");
    EXPECT_EQ(alarm.messageArguments, drop.arguments);
    EXPECT_THROW(message("no_such_message"), std::logic_error);
    // an input's function is words: said in the message's language
    const Message timeout =
        message("sensor_timeout", {bilingual("IN11 (tool released)", "IN11 (松刀到位)"), "1", "10.0", "slib-g.nc", "46"});
    EXPECT_EQ(timeout.english(), "IN11 (tool released) never became 1: waited 10.0 s at slib-g.nc:46");
    EXPECT_EQ(timeout.in(MessageLanguage::Chinese), "IN11 (松刀到位)未变为1：在slib-g.nc:46处已等待10.0秒");
}

} // namespace
} // namespace m350
