#!/usr/bin/env python3
"""Regenerate resources/parameters/m350-parameters.tsv from the extracted M350 parameter table.

Usage: scripts/gen-parameter-catalogue.py [SOURCE.md] [OUTPUT.tsv]
Defaults: /work/shared/reference/m350-parameters.md -> resources/parameters/m350-parameters.tsv

The TSV is committed; the product reads only the TSV, never the markdown. See
resources/parameters/README.md for the column meanings and the source's known quirks.
"""

import re
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
DEFAULT_SOURCE = Path("/work/shared/reference/m350-parameters.md")
DEFAULT_OUTPUT = REPO / "resources" / "parameters" / "m350-parameters.tsv"

HEADER = ["number", "group", "group_zh", "group_en", "name_zh", "name_en", "unit", "type",
          "min", "max", "options", "default", "hidden"]
SOURCE_COLUMNS = 11  # N | macro | group | zh | en | unit | type | min..max | options | default | user
TYPES = {"int", "real", "select"}

# The source's group cell is "<m> <en> <zh>", which cannot tell that page 6's Chinese title starts
# with "IO"; the controller's own string (UI message 69) is "IO参数及自定义按键".
GROUP_ZH_OVERRIDES = {6: "IO参数及自定义按键"}

NUMBER = re.compile(r"-?\d+(?:\.\d+)?")

# The firmware's `eng` file gives some hidden parameters their Chinese name, stored in GBK; the
# extraction read those bytes as Latin-1 ("×Ô¶¨ÒåG´úÂëºÅ" is 自定义G代码号). Such text is decoded
# back (repair_gbk). An English name that is then Chinese would show Chinese on the English
# panel: these English names are ours, translated from the Chinese.
ENGLISH_NAMES = {
    71: "Enable G0 motion planning",              # G0段运动规划使能
    134: "Tool setting start position",           # 对刀初始位置
    242: "Main screen layout",                    # 主界面显示方案
    249: "J parameter gradient",                  # J参数梯度
    254: "Toolpath view width",                   # 刀轨宽度
    255: "Toolpath view height",                  # 刀轨高度
    256: "Toolpath view thickness",               # 刀轨厚度
    257: "Toolpath canvas thickness in relief mode",  # 雕像模式下刀轨画板厚度
    258: "Canvas origin X position",              # 画板原点X轴位置
    259: "Canvas origin Y position",              # 画板原点Y轴位置
    260: "Canvas origin Z position",              # 画板原点Z轴位置
    270: "User permission key",                   # 用户权限密匙
    969: "Custom G code number",                  # 自定义G代码号 (Gxx, 100-200: G100-G199)
}
# The same for options: (parameter, value) -> English. The language options of 240 name each
# language in its own script in `eng` (中文, Рус); the English panel says it in English.
ENGLISH_OPTIONS = {
    (71, 0): "No", (71, 1): "Yes",                               # 禁止, 使能
    (134, 0): "Current position", (134, 1): "Fixed position",    # 当前位置, 固定位置
    (240, 1): "Chinese", (240, 2): "Russian",                    # 中文, Рус
    (242, 0): "Layout 1", (242, 1): "Layout 2", (242, 2): "Layout 3",  # 方案1-3
}


def repair_gbk(text, where):
    """GBK text read as Latin-1 back to what it says; other text unchanged. Latin-1 letters do not
    occur in the source's names otherwise (Chinese, English, Russian only)."""
    if not any(0x80 <= ord(c) <= 0xFF for c in text):
        return text
    try:
        return text.encode("latin-1").decode("gbk")
    except (UnicodeEncodeError, UnicodeDecodeError) as e:
        raise ValueError(f"{where}: {text!r} is neither real text nor GBK read as Latin-1 ({e})")


def has_cjk(text):
    return any(is_cjk(c) for c in text)


def english_name(number, en, where):
    en = repair_gbk(en, where)
    if has_cjk(en):
        if number not in ENGLISH_NAMES:
            raise ValueError(f"{where}: the English name of parameter {number} is Chinese ({en}): "
                             "give it one in ENGLISH_NAMES")
        return ENGLISH_NAMES[number]
    return en


def is_cjk(ch):
    # CJK punctuation, ideographs and full-width forms all sit at or above U+3000; the mojibake in
    # some English names (Latin-1 read as text) stays below it.
    return ord(ch) >= 0x3000


def split_zh_en(text):
    """Split "zh/en" at the first '/' after which no CJK follows ("脉冲/度/pulse/deg" -> 脉冲/度, pulse/deg).
    ParameterCatalogue.cpp applies the same rule when it reads the options column."""
    for i, ch in enumerate(text):
        if ch == "/" and not any(is_cjk(c) for c in text[i + 1:]):
            return text[:i], text[i + 1:]
    return None


def split_group(cell):
    m = re.fullmatch(r"(\d+)\s*(.*)", cell)
    if not m:
        raise ValueError(f"group cell {cell!r} does not start with a number")
    group, rest = int(m.group(1)), m.group(2)
    tokens = rest.split()
    first_zh = next((i for i, t in enumerate(tokens) if any(is_cjk(c) for c in t)), len(tokens))
    en, zh = " ".join(tokens[:first_zh]), " ".join(tokens[first_zh:])
    return group, GROUP_ZH_OVERRIDES.get(group, zh), en


def parse_options(cell, number, where):
    options = []
    for option in (o.strip() for o in cell.split(";") if o.strip()):
        value, eq, text = option.partition("=")
        if not eq or not NUMBER.fullmatch(value.strip()):
            raise ValueError(f"{where}: option {option!r} is not value=zh/en")
        # split before repairing: the mojibake half holds no CJK, so the split rule still holds
        parts = split_zh_en(text.strip())
        if parts is None or not parts[0].strip() or not parts[1].strip():
            raise ValueError(f"{where}: option {option!r} does not split into zh/en")
        zh, en = repair_gbk(parts[0], where), repair_gbk(parts[1], where)
        en = ENGLISH_OPTIONS.get((number, int(float(value))), en)
        if has_cjk(en):
            raise ValueError(f"{where}: option {option!r} has a Chinese English name: give it one "
                             "in ENGLISH_OPTIONS")
        options.append(f"{value.strip()}={zh}/{en}")
    return "; ".join(options)


def convert(source_text):
    rows = []
    for line_number, line in enumerate(source_text.splitlines(), start=1):
        if not re.match(r"^\|\s*\d", line):
            continue
        where = f"line {line_number}"
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) != SOURCE_COLUMNS:
            raise ValueError(f"{where}: expected {SOURCE_COLUMNS} cells, found {len(cells)}")
        number, _macro, group_cell, zh, en, unit, typ, min_max, options, default, _user = cells
        if typ not in TYPES:
            raise ValueError(f"{where}: unknown type {typ!r}")
        low, sep, high = min_max.partition("..")
        if not sep or not NUMBER.fullmatch(low) or not NUMBER.fullmatch(high):
            raise ValueError(f"{where}: range {min_max!r} is not min..max")
        if default and not NUMBER.fullmatch(default):
            raise ValueError(f"{where}: default {default!r} is not a number")
        group, group_zh, group_en = split_group(group_cell)
        zh = repair_gbk(zh, where)
        en = english_name(int(number), en, where)
        # Rows 950-953 (int/real) carry an empty "0= ; 1=" placeholder; options mean nothing there.
        options = parse_options(options, int(number), where) if typ == "select" else ""
        if typ == "select" and not options:
            raise ValueError(f"{where}: select parameter without options")
        rows.append([number, str(group), group_zh, group_en, zh, en, unit, typ, low, high, options,
                     default, "1" if group == 0 else "0"])
    return rows


def main(argv):
    source = Path(argv[1]) if len(argv) > 1 else DEFAULT_SOURCE
    output = Path(argv[2]) if len(argv) > 2 else DEFAULT_OUTPUT
    # errors="replace" keeps the output valid UTF-8 even if a mojibake cell holds undecodable bytes.
    rows = convert(source.read_bytes().decode("utf-8", errors="replace"))
    numbers = [int(r[0]) for r in rows]
    if len(set(numbers)) != len(numbers):
        raise ValueError("duplicate parameter numbers in the source")
    for row in [HEADER] + rows:
        for field in row:
            if any(c in field for c in "\t\r\n"):
                raise ValueError(f"parameter {row[0]}: field {field!r} holds a tab or line break")
    output.parent.mkdir(parents=True, exist_ok=True)
    with output.open("w", encoding="utf-8", newline="\n") as out:
        for row in [HEADER] + rows:
            out.write("\t".join(row) + "\n")
    print(f"wrote {len(rows)} parameters to {output}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
