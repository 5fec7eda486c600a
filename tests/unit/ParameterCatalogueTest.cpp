// The bundled parameter catalogue against the extracted M350 parameter table
// (resources/parameters/README.md says where each value comes from).
#include "core/params/ParameterCatalogue.h"
#include "core/params/ParameterTable.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>

using m350::params::ParameterCatalogue;
using m350::params::ParameterInfo;
using m350::params::ParameterTable;
using testing::HasSubstr;

namespace {

const ParameterCatalogue& bundled() {
    static const ParameterCatalogue catalogue = [] {
        auto loaded = ParameterCatalogue::load(ParameterCatalogue::bundledPath());
        if (auto* error = std::get_if<std::string>(&loaded)) ADD_FAILURE() << *error;
        auto* ok = std::get_if<ParameterCatalogue>(&loaded);
        return ok != nullptr ? *ok : ParameterCatalogue{};
    }();
    return catalogue;
}

const ParameterInfo& param(int number) {
    const ParameterInfo* p = bundled().find(number);
    if (p == nullptr) throw std::runtime_error("parameter " + std::to_string(number) + " missing");
    return *p;
}

std::string loadError(const std::string& name, const std::string& text) {
    std::string path = testing::TempDir() + name;
    std::ofstream(path, std::ios::binary) << text;
    auto loaded = ParameterCatalogue::load(path);
    auto* error = std::get_if<std::string>(&loaded);
    return error != nullptr ? *error : std::string("(loaded without error)");
}

const std::string kHeader =
    "number\tgroup\tgroup_zh\tgroup_en\tname_zh\tname_en\tunit\ttype\tmin\tmax\toptions\tdefault\thidden\n";

} // namespace

TEST(ParameterCatalogue, LoadsAllBundledParameters) {
    EXPECT_EQ(bundled().all().size(), 584u);
    EXPECT_EQ(bundled().find(4), nullptr); // not in the M350's list
    EXPECT_NE(bundled().find(1105), nullptr); // CAM-teach forms go beyond ParameterTable
}

TEST(ParameterCatalogue, CurrentToolAndMagazine) {
    const ParameterInfo& current = param(800);
    EXPECT_EQ(current.nameZh, "当前刀具号");
    EXPECT_EQ(current.nameEn, "Current tool No.");
    EXPECT_EQ(current.group, 14);
    EXPECT_EQ(current.groupEn, "Tools");
    EXPECT_EQ(current.groupZh, "刀具参数");
    EXPECT_FALSE(current.hidden);

    const ParameterInfo& capacity = param(801);
    EXPECT_EQ(capacity.type, ParameterInfo::Type::Int);
    EXPECT_EQ(capacity.min, 0);
    EXPECT_EQ(capacity.max, 20);
    EXPECT_EQ(capacity.defaultValue, 12);

    const ParameterInfo& magazine = param(802);
    EXPECT_EQ(magazine.type, ParameterInfo::Type::Select);
    ASSERT_EQ(magazine.options.size(), 5u);
    EXPECT_EQ(magazine.options[0].value, 0);
    EXPECT_EQ(magazine.options[0].zh, "无刀库");
    EXPECT_EQ(magazine.options[0].en, "NULL");
    EXPECT_EQ(magazine.options[4].value, 4);
    EXPECT_EQ(magazine.options[4].zh, "圆盘刀库");
    EXPECT_EQ(magazine.options[4].en, "Servo disc");
}

TEST(ParameterCatalogue, SpotChecks) {
    const ParameterInfo& homePrompt = param(127);
    ASSERT_EQ(homePrompt.options.size(), 2u);
    EXPECT_EQ(homePrompt.options[0].zh, "是");
    EXPECT_EQ(homePrompt.options[0].en, "Yes");
    EXPECT_EQ(homePrompt.options[1].value, 1);
    EXPECT_EQ(homePrompt.options[1].en, "No");

    EXPECT_EQ(param(129).unit, "mm");
    EXPECT_EQ(param(129).type, ParameterInfo::Type::Real);
    EXPECT_THAT(param(930).nameEn, HasSubstr("T01 Z offset"));
    EXPECT_EQ(param(930).unit, "mm");
    EXPECT_EQ(param(92).group, 6);
    EXPECT_EQ(param(92).groupZh, "IO参数及自定义按键"); // the controller's page title, not "参数及自定义按键"
    EXPECT_EQ(param(92).groupEn, "IO");
}

TEST(ParameterCatalogue, OptionNamesMayHoldSlashes) {
    const ParameterInfo& fourthUnit = param(7);
    ASSERT_EQ(fourthUnit.options.size(), 2u);
    EXPECT_EQ(fourthUnit.options[0].zh, "脉冲/度");
    EXPECT_EQ(fourthUnit.options[0].en, "pulse/deg");
    EXPECT_EQ(param(79).options[1].zh, "伺服主轴");
    EXPECT_EQ(param(79).options[1].en, "Plu/dir");
}

TEST(ParameterCatalogue, HiddenRows) {
    const ParameterInfo& axisMapping = param(22);
    EXPECT_EQ(axisMapping.group, 0);
    EXPECT_TRUE(axisMapping.hidden);
    EXPECT_EQ(axisMapping.nameEn, "Enable axis mapping function");
    for (const ParameterInfo& p : bundled().all()) EXPECT_EQ(p.hidden, p.group == 0) << p.number;
}

TEST(ParameterCatalogue, ValidateInt) {
    EXPECT_EQ(bundled().validate(801, 0), std::nullopt);
    EXPECT_EQ(bundled().validate(801, 20), std::nullopt);
    EXPECT_EQ(bundled().validate(801, 25),
              "parameter 801 (Total number of tools) must be a whole number from 0 to 20, not 25");
    EXPECT_THAT(bundled().validate(801, 2.5).value_or(m350::Message{}).english(), HasSubstr("whole number from 0 to 20, not 2.5"));
    EXPECT_TRUE(bundled().validate(801, -1).has_value());
}

TEST(ParameterCatalogue, ValidateReal) {
    EXPECT_EQ(bundled().validate(129, 12.345), std::nullopt);
    EXPECT_EQ(bundled().validate(129, 0), std::nullopt);
    EXPECT_EQ(bundled().validate(129, 120),
              "parameter 129 (Floating tool set thickness) must be from 0 to 99, not 120");
    EXPECT_TRUE(bundled().validate(129, std::nan("")).has_value());
}

TEST(ParameterCatalogue, ValidateSelect) {
    EXPECT_EQ(bundled().validate(802, 4), std::nullopt);
    auto message = bundled().validate(802, 5);
    ASSERT_TRUE(message.has_value());
    EXPECT_EQ(message->id, "param_must_be_one_of");
    EXPECT_THAT(message->english(), HasSubstr("parameter 802 (Tool magazine type) must be one of 0 (NULL), "));
    EXPECT_THAT(message->english(), HasSubstr("4 (Servo disc), not 5"));
    // the panel's and `m350-sim --lang zh_CN`'s words: the parameter's Chinese name and choices
    EXPECT_THAT(message->in(m350::MessageLanguage::Chinese), HasSubstr("参数802（刀库类型）须为0（无刀库）、1（多工序）"));
    EXPECT_THAT(message->in(m350::MessageLanguage::Chinese), HasSubstr("4（圆盘刀库）之一，不能为5"));
    EXPECT_TRUE(bundled().validate(802, 1.5).has_value());
    ASSERT_TRUE(bundled().validate(4, 0).has_value());
    EXPECT_EQ(bundled().validate(4, 0)->english(), "parameter 4 is not in the catalogue");
}

TEST(ParameterCatalogue, ApplyDefaults) {
    ParameterTable table;
    bundled().applyDefaults(table);
    EXPECT_EQ(table.get(61), 3000); // default operating speed
    EXPECT_EQ(table.get(801), 12);
    EXPECT_EQ(table.get(1), 200);
    EXPECT_EQ(table.get(24), 3); // hidden rows too
}

TEST(ParameterCatalogue, MalformedRowNamesFileAndLine) {
    std::string error = loadError("param-bad-columns.tsv",
                                  kHeader + "0\t1\t机床参数\tMachine\t电机起跳速度\tMotor starting speed\tmm/min\t"
                                            "real\t1\t999\t\t50\t0\n"
                                            "1\t1\tonly\tfive\tfields\n");
    EXPECT_THAT(error, HasSubstr("param-bad-columns.tsv:3: "));
    EXPECT_THAT(error, HasSubstr("expected 13 tab-separated fields, found 5"));
}

TEST(ParameterCatalogue, MalformedValuesAreRefused) {
    std::string row = "5\t1\t\tMachine\tzh\ten\t\t";
    EXPECT_THAT(loadError("param-bad-type.tsv", kHeader + row + "bool\t0\t1\t\t0\t0\n"),
                HasSubstr("param-bad-type.tsv:2: type 'bool'"));
    EXPECT_THAT(loadError("param-bad-min.tsv", kHeader + row + "real\tx\t1\t\t0\t0\n"),
                HasSubstr(":2: min 'x' is not a number"));
    EXPECT_THAT(loadError("param-bad-option.tsv", kHeader + row + "select\t0\t1\t0=none\t0\t0\n"),
                HasSubstr(":2: option '0=none' is not value=zh/en"));
    EXPECT_THAT(loadError("param-dup.tsv", kHeader + row + "real\t0\t1\t\t0\t0\n" + row + "real\t0\t1\t\t0\t0\n"),
                HasSubstr(":3: parameter 5 appears twice"));
    EXPECT_THAT(loadError("param-bad-header.tsv", "N\tname\n"), HasSubstr("param-bad-header.tsv:1: header"));
    EXPECT_THAT(loadError("param-missing.tsv/none", ""), HasSubstr("cannot open"));
}

// Some of the firmware's English names are GBK-encoded Chinese; the extraction once read them as
// Latin-1 (parameter 969 showed as ×Ô¶¨ÒåG´úÂëºÅ in the importer's report). Every name now reads
// as text: the hidden parameters have English names, the language options say the language.
TEST(ParameterCatalogue, EveryNameIsRealTextInBothLanguages) {
    EXPECT_EQ(param(969).nameEn, "Custom G code number");
    EXPECT_EQ(param(71).nameEn, "Enable G0 motion planning");
    EXPECT_EQ(param(71).options[1].en, "Yes");
    EXPECT_EQ(param(134).options[1].en, "Fixed position");
    const ParameterInfo& language = param(240);
    ASSERT_EQ(language.options.size(), 4u);
    EXPECT_EQ(language.options[1].zh, "中文");
    EXPECT_EQ(language.options[1].en, "Chinese");
    EXPECT_EQ(language.options[2].zh, "Рус");
    EXPECT_EQ(language.options[2].en, "Russian");
    auto latin1Run = [](const std::string& text) {
        for (std::size_t i = 0; i + 3 < text.size(); ++i) {
            auto a = static_cast<unsigned char>(text[i]), b = static_cast<unsigned char>(text[i + 2]);
            if ((a == 0xC2 || a == 0xC3) && (b == 0xC2 || b == 0xC3)) {
                return true;
            }
        }
        return false;
    };
    for (const ParameterInfo& p : bundled().all()) {
        EXPECT_FALSE(latin1Run(p.nameEn) || latin1Run(p.nameZh)) << p.number << ": " << p.nameZh << " " << p.nameEn;
        for (const auto& option : p.options) {
            EXPECT_FALSE(latin1Run(option.en) || latin1Run(option.zh)) << p.number << ": " << option.en;
            // the English panel shows English: no Chinese in an English name
            EXPECT_EQ(option.en.find_first_of("\xe4\xe5\xe6\xe7\xe8\xe9"), std::string::npos) << p.number;
        }
        EXPECT_EQ(p.nameEn.find_first_of("\xe4\xe5\xe6\xe7\xe8\xe9"), std::string::npos) << p.number << ": " << p.nameEn;
    }
}

// 自定义G代码号 in GBK, written into the catalogue as bytes and as those bytes read as Latin-1:
// both are refused naming the line, so such text never reaches a panel or an import report.
TEST(ParameterCatalogue, GbkBytesAndGbkReadAsLatin1AreRefused) {
    const std::string gbk = "\xd7\xd4\xb6\xa8\xd2\xe5G\xb4\xfa\xc2\xeb\xba\xc5";
    std::string latin1; // each byte as the code point U+00XX, in UTF-8
    for (char c : gbk) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte < 0x80) {
            latin1 += c;
        } else {
            latin1 += static_cast<char>(0xC0 | (byte >> 6));
            latin1 += static_cast<char>(0x80 | (byte & 0x3F));
        }
    }
    ASSERT_EQ(latin1, "×Ô¶¨ÒåG´úÂëºÅ");
    const std::string before = "969\t0\t\thidden\tT3主轴速度\t";
    const std::string after = "\tGxx\tint\t100\t200\t\t0\t1\n";
    std::string raw = loadError("param-gbk.tsv", kHeader + before + gbk + after);
    EXPECT_THAT(raw, HasSubstr("param-gbk.tsv:2: name_en is not UTF-8 at its byte 1"));
    EXPECT_EQ(raw.find(gbk), std::string::npos); // the message stays UTF-8 itself
    EXPECT_THAT(loadError("param-latin1.tsv", kHeader + before + latin1 + after),
                HasSubstr("param-latin1.tsv:2: name_en '×Ô¶¨ÒåG´úÂëºÅ' looks like GBK text read as Latin-1"));
    EXPECT_THAT(loadError("param-gbk-option.tsv",
                          kHeader + "71\t0\t\thidden\tG0\tG0 planning\t\tselect\t0\t1\t0=禁止/" + latin1 + "\t0\t1\n"),
                HasSubstr(":2: option name"));
    // the same name in UTF-8 loads
    std::string path = testing::TempDir() + "param-utf8.tsv";
    std::ofstream(path, std::ios::binary) << kHeader + before + "自定义G代码号" + after;
    auto loaded = ParameterCatalogue::load(path);
    ASSERT_TRUE(std::holds_alternative<ParameterCatalogue>(loaded)) << std::get<std::string>(loaded);
    EXPECT_EQ(std::get<ParameterCatalogue>(loaded).find(969)->nameEn, "自定义G代码号");
}
