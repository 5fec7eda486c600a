#!/usr/bin/env bash
# Drives scripts/check-layers.sh over small trees made here: a clean one passes, and each way of
# breaking the layering fails naming the file and line.
set -euo pipefail
checker="$1"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

tree() { # NAME: a clean tree with core/common, core/config, ui/pages, ui/panel, app/sim
    local t="$work/$1"
    mkdir -p "$t/core/common" "$t/core/config" "$t/ui/pages" "$t/ui/panel" "$t/app/sim"
    echo '#pragma once' >"$t/core/common/Alarm.h"
    printf '#include "core/common/Alarm.h"\n' >"$t/core/config/MachineConfig.h"
    printf '#include "core/config/MachineConfig.h"\n' >"$t/ui/pages/Page.h"
    printf '#include "ui/pages/Page.h"\n#include "core/common/Alarm.h"\n' >"$t/ui/panel/MainWindow.cpp"
    printf '#include "core/config/MachineConfig.h"\n' >"$t/app/sim/main.cpp"
    echo "$t"
}

expect() { # WHAT PASS|FAIL TREE [TEXT]
    local what="$1" want="$2" t="$3" text="${4:-}" out status=0
    out=$(bash "$checker" "$t" 2>&1) || status=$?
    if [[ "$want" == PASS && $status -ne 0 ]] || [[ "$want" == FAIL && $status -eq 0 ]]; then
        echo "FAIL: $what: exit $status, wanted $want"; echo "$out"; failures=$((failures + 1)); return
    fi
    if [[ -n "$text" && "$out" != *"$text"* ]]; then
        echo "FAIL: $what: the output does not name '$text'"; echo "$out"; failures=$((failures + 1)); return
    fi
    echo "ok: $what"
}

expect "a clean tree" PASS "$(tree clean)"

t=$(tree backward)
printf '// the config of the machine\n#include "core/config/MachineConfig.h"\n' >>"$t/core/common/Alarm.h"
expect "core/common including core/config" FAIL "$t" "core/common/Alarm.h:3: core/common includes core/config/MachineConfig.h"

t=$(tree cycle)
printf '#include "ui/panel/MainWindow.h"\n' >>"$t/ui/pages/Page.h"
expect "ui/pages including ui/panel" FAIL "$t" "ui/pages/Page.h:2"

t=$(tree upward)
printf '#include "ui/pages/Page.h"\n' >"$t/core/config/MachineConfig.cpp"
expect "core including ui" FAIL "$t" "core/config/MachineConfig.cpp:1: core/ includes ui/pages/Page.h"

t=$(tree unknown)
mkdir -p "$t/core/newthing"; echo '#pragma once' >"$t/core/newthing/Thing.h"
expect "a folder in no layer list" FAIL "$t" "core/newthing is in no layer list"

echo "$(( 5 - failures )) passed, $failures failed"
((failures == 0))
