#!/usr/bin/env bash
# Refreshes translations/m350_zh_CN.ts and m350_en.ts from the panel's sources (lupdate), then
# fills in the Chinese: from the firmware's string table where a string names its msg id
# (tr("Go Home", "msg 315")), else from translations/panel-strings.zh.tsv. Run it after adding
# or changing an on-screen string, and commit the .ts files.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
LUPDATE=$(command -v lupdate || echo /usr/lib/qt6/bin/lupdate)
# its parser warns about every `namespace m350::ui {` definition; the script below fixes the contexts
"$LUPDATE" -silent -no-obsolete -locations none ui -ts translations/m350_zh_CN.ts translations/m350_en.ts 2>&1 |
    { grep -v "Qualifying with unknown namespace" || true; }
python3 scripts/fill-translations.py
