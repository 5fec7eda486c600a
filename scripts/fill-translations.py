#!/usr/bin/env python3
"""Fills translations/m350_zh_CN.ts and m350_en.ts after lupdate.

Chinese comes from the firmware's own string table (resources/firmware-ui-strings.tsv) when the
source names its id in the disambiguation (tr("Go Home", "msg 315")), else from our own table
translations/panel-strings.zh.tsv (English source, tab, Chinese), else from a firmware string
whose English is the same. English is the source itself. Strings left without Chinese are
listed and make the script exit 1, so none ships untranslated by accident.
"""
import csv
import re
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
FIRMWARE = ROOT / "resources" / "firmware-ui-strings.tsv"
OURS = ROOT / "translations" / "panel-strings.zh.tsv"


def read_firmware():
    by_id, by_en = {}, {}
    with FIRMWARE.open(encoding="utf-8") as f:
        for row in csv.reader(f, delimiter="\t", quoting=csv.QUOTE_NONE):
            if len(row) < 3 or not row[0].isdigit():
                continue
            zh, en = row[1].strip(), row[2].strip()
            by_id[int(row[0])] = zh
            if en and zh:
                by_en.setdefault(en, zh)
    return by_id, by_en


def read_ours():
    table = {}
    if OURS.exists():
        for line in OURS.read_text(encoding="utf-8").splitlines():
            if not line.strip() or line.startswith("#"):
                continue
            source, _, zh = line.partition("\t")
            table[source.replace("\\n", "\n")] = zh.replace("\\n", "\n")
    return table


def fill(ts_path, translate):
    tree = ET.parse(ts_path)
    # lupdate's parser does not follow `namespace m350::ui {`; tr() uses the qualified class name
    for name in tree.iter("name"):
        if name.text and "::" not in name.text:
            name.text = "m350::ui::" + name.text
    missing = []
    for message in tree.iter("message"):
        source = message.findtext("source") or ""
        comment = message.findtext("comment") or ""
        text = translate(source, comment)
        translation = message.find("translation")
        if translation is None:
            translation = ET.SubElement(message, "translation")
        if text is None:
            missing.append((source, comment))
            translation.set("type", "unfinished")
            translation.text = ""
        else:
            translation.attrib.pop("type", None)
            translation.text = text
    tree.write(ts_path, encoding="utf-8", xml_declaration=True)
    return missing


def main():
    by_id, by_en = read_firmware()
    ours = read_ours()

    def chinese(source, comment):
        m = re.fullmatch(r"msg (\d+)", comment)
        if m and int(m.group(1)) in by_id and by_id[int(m.group(1))]:
            return by_id[int(m.group(1))]
        if source in ours:
            return ours[source]
        return by_en.get(source)

    missing = fill(ROOT / "translations" / "m350_zh_CN.ts", chinese)
    fill(ROOT / "translations" / "m350_en.ts", lambda source, comment: source)
    for source, comment in missing:
        print(f"no Chinese for {source!r} ({comment})" if comment else f"no Chinese for {source!r}")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
