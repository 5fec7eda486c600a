#!/usr/bin/env bash
# Renders the README's screenshots: each replay of docs/replays/ played by m350-hmi under Xvfb,
# in Chinese and in English, into docs/screenshots/PAGE-LANG.png.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
BUILD=${1:-build}
for replay in docs/replays/*.jsonl; do
    page=$(basename "$replay" .jsonl)
    for lang in zh_CN en; do
        xvfb-run -a "$BUILD/app/m350-hmi" --lang "$lang" --replay "$replay" --screenshot "docs/screenshots/$page-$lang.png" 2>/dev/null
    done
done
ls docs/screenshots
