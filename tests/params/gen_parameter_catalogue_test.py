#!/usr/bin/env python3
"""scripts/gen-parameter-catalogue.py on rows as the extracted table holds them: GBK names read as
Latin-1 come out as real text (Chinese where zh, our English where en), and a name the script
cannot make real is refused. Usage: gen_parameter_catalogue_test.py SCRIPT"""

import importlib.util
import sys

spec = importlib.util.spec_from_file_location("gen", sys.argv[1])
gen = importlib.util.module_from_spec(spec)
spec.loader.exec_module(gen)


def latin1(text):
    """What the extraction made of GBK text: each byte as the code point U+00XX."""
    return text.encode("gbk").decode("latin-1")


def row(number, zh, en, typ="int", options="", group="0 hidden"):
    return f"| {number} | #{number + 500} | {group} | {zh} | {en} | Gxx | {typ} | 100..200 | {options} | 0 | 0 |"


failures = []


def check(condition, what):
    if not condition:
        failures.append(what)


# 969: the English name is GBK Chinese read as Latin-1; the table's English replaces it
assert latin1("自定义G代码号") == "×Ô¶¨ÒåG´úÂëºÅ"
rows = gen.convert(row(969, "T3主轴速度", latin1("自定义G代码号")))
check(rows[0][4] == "T3主轴速度", f"969 zh: {rows[0][4]}")
check(rows[0][5] == "Custom G code number", f"969 en: {rows[0][5]}")

# options: zh/en split before the repair; a Chinese English option name takes the table's
rows = gen.convert(row(71, "G0段运动规划使能", latin1("G0段运动规划使能"), "select",
                       f"0=禁止/{latin1('禁止')}; 1=使能/{latin1('使能')}"))
check(rows[0][5] == "Enable G0 motion planning", f"71 en: {rows[0][5]}")
check(rows[0][10] == "0=禁止/No; 1=使能/Yes", f"71 options: {rows[0][10]}")

# Cyrillic in GBK decodes too; 240's language options say the language in English
rows = gen.convert(row(240, "语言设置", "Language", "select",
                       f"0=Eng/Eng; 1=中文/{latin1('中文')}; 2=Рус/{latin1('Рус')}; 3=Other/Other", "15 System 系统参数"))
check(rows[0][10] == "0=Eng/Eng; 1=中文/Chinese; 2=Рус/Russian; 3=Other/Other", f"240 options: {rows[0][10]}")

# a Chinese English name the tables do not cover is refused, not written
try:
    gen.convert(row(968, "T2主轴速度", latin1("主轴速度")))
    failures.append("968: a Chinese English name was written")
except ValueError as e:
    check("ENGLISH_NAMES" in str(e), f"968 refusal: {e}")

# plain rows are unchanged
rows = gen.convert(row(801, "刀库容量", "Total number of tools", group="14 Tools 刀具参数"))
check(rows[0][4:6] == ["刀库容量", "Total number of tools"], f"801: {rows[0][4:6]}")

if failures:
    print("\n".join(failures))
    sys.exit(1)
print("ok")
