#!/usr/bin/env bash
# Renders the README's screenshots: each replay of docs/replays/ played by m350-hmi under Xvfb,
# in Chinese and in English, into docs/screenshots/PAGE-LANG.png. A replay with a PAGE.args beside
# it runs on a copy of the bundled machine its first word names, with the rest as extra options.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
BUILD=${1:-build}
for replay in docs/replays/*.jsonl; do
    page=$(basename "$replay" .jsonl)
    for lang in zh_CN en; do
        extra=()
        if [[ -f "docs/replays/$page.args" ]]; then
            read -r -a words < "docs/replays/$page.args"
            scratch=$(mktemp -d)
            cp -r "resources/machines/${words[0]}" "$scratch/machine"
            extra=(--config "$scratch/machine" "${words[@]:1}")
        fi
        # their programs sit beside them: the U disk, the one a replay may load from besides the machine's
        xvfb-run -a "$BUILD/app/m350-hmi" --lang "$lang" --replay "$replay" --programs docs/replays "${extra[@]}" \
            --screenshot "docs/screenshots/$page-$lang.png" 2>/dev/null
        [[ -z "${scratch:-}" ]] || rm -rf "$scratch"
        scratch=
    done
done
# 训练 Training: its start page, an attempt under way and a verdict (docs/training/)
for lang in zh_CN en; do
    xvfb-run -a "$BUILD/app/m350-hmi" --lang "$lang" --training --trainee 王伟 \
        --screenshot "docs/screenshots/training-start-$lang.png" 2>/dev/null
    for shot in attempt verdict; do
        xvfb-run -a "$BUILD/app/m350-hmi" --lang "$lang" --training --trainee 王伟 --exercise resources/exercises/pocket-taught-off \
            --replay "docs/training/$shot.jsonl" --screenshot "docs/screenshots/training-$shot-$lang.png" 2>/dev/null
    done
done
# a trainer's review of the correct pocket-taught-off attempt, mid tool change (O20000 on slib-g.nc)
for lang in zh_CN en; do
    xvfb-run -a "$BUILD/app/m350-hmi" --lang "$lang" --review tests/training/attempts/pocket-taught-off/correct.jsonl \
        --exercise resources/exercises/pocket-taught-off --review-until 15 \
        --screenshot "docs/screenshots/review-$lang.png" 2>/dev/null
done
ls docs/screenshots
