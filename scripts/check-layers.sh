#!/usr/bin/env bash
# The layering rule of docs/architecture.md, checked over the #include lines of a source tree:
# a folder of core/ (or ui/, or app/) may include only folders listed before it in its layer list
# below (and itself). A backward include, and so any cycle between folders, fails with the file, the
# line and both folders named. A folder missing from the lists fails too, so a new folder gets a
# place in the rule before it gets code. Usage: check-layers.sh [ROOT] (default: the repository).
set -euo pipefail

root="${1:-$(dirname "${BASH_SOURCE[0]}")/..}"

# Bottom first. core never includes ui or app; ui never includes app.
core_layers=(common files params gcode machine macro tools interp check devices config backup controller preview training)
ui_layers=(i18n session widgets view program pages actions panel replay training)
app_layers=(sim hmi)

rank_of() { # LIST... -- NAME: the index of NAME in LIST, or nothing
    local name="${*: -1}" i=0
    for layer in "${@:1:$#-2}"; do
        [[ "$layer" == "$name" ]] && { echo "$i"; return; }
        i=$((i + 1))
    done
}

# part rank: core 0, ui 1, app 2; a file may include only parts at or below its own.
part_rank() {
    case "$1" in core) echo 0 ;; ui) echo 1 ;; app) echo 2 ;; *) echo "" ;; esac
}

layer_rank() { # PART FOLDER
    case "$1" in
    core) rank_of "${core_layers[@]}" -- "$2" ;;
    ui) rank_of "${ui_layers[@]}" -- "$2" ;;
    app) rank_of "${app_layers[@]}" -- "$2" ;;
    esac
}

failures=0
complain() {
    echo "check-layers: $*" >&2
    failures=$((failures + 1))
}

for part in core ui app; do
    [[ -d "$root/$part" ]] || continue
    for dir in "$root/$part"/*/; do
        folder=$(basename "$dir")
        [[ -n "$(find "$dir" -name '*.h' -o -name '*.cpp' | head -1)" ]] || continue
        [[ -n "$(layer_rank "$part" "$folder")" ]] ||
            complain "$part/$folder is in no layer list of scripts/check-layers.sh: give it its place"
    done
    while IFS= read -r hit; do
        file="${hit%%:*}"
        rest="${hit#*:}"
        line="${rest%%:*}"
        target=$(sed -E 's/^[^"]*"([^"]+)".*/\1/' <<<"${rest#*:}")
        relative="${file#"$root"/}"
        from_part="${relative%%/*}"
        from_folder=$(cut -d/ -f2 <<<"$relative")
        to_part="${target%%/*}"
        to_folder=$(cut -d/ -f2 <<<"$target")
        [[ -n "$(part_rank "$to_part")" ]] || continue
        if (($(part_rank "$to_part") > $(part_rank "$from_part"))); then
            complain "$relative:$line: $from_part/ includes $target: $to_part/ is above $from_part/"
            continue
        fi
        [[ "$to_part" == "$from_part" ]] || continue
        from_rank=$(layer_rank "$from_part" "$from_folder")
        to_rank=$(layer_rank "$to_part" "$to_folder")
        [[ -n "$from_rank" && -n "$to_rank" ]] || continue
        if ((to_rank > from_rank)); then
            complain "$relative:$line: $from_part/$from_folder includes $target: $to_part/$to_folder is above it"
        fi
    done < <(grep -rnE '^[[:space:]]*#[[:space:]]*include[[:space:]]+"(core|ui|app)/' "$root/$part" \
        --include='*.h' --include='*.cpp' || true)
done

if ((failures > 0)); then
    echo "check-layers: $failures include(s) break the layering (docs/architecture.md, Layers)" >&2
    exit 1
fi
echo "check-layers: every include of core/, ui/ and app/ goes down the layers"
