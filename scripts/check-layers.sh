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

# Ranks by name, looked up without a subshell: the tree has thousands of include lines.
declare -A part_rank=([core]=0 [ui]=1 [app]=2)
declare -A layer_rank # PART/FOLDER -> its index in PART's list
for i in "${!core_layers[@]}"; do layer_rank["core/${core_layers[$i]}"]=$i; done
for i in "${!ui_layers[@]}"; do layer_rank["ui/${ui_layers[$i]}"]=$i; done
for i in "${!app_layers[@]}"; do layer_rank["app/${app_layers[$i]}"]=$i; done

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
        [[ -n "${layer_rank[$part/$folder]:-}" ]] ||
            complain "$part/$folder is in no layer list of scripts/check-layers.sh: give it its place"
    done
    include_line='^([^:]+):([0-9]+):[^"]*"([^"]+)"'
    while IFS= read -r hit; do
        [[ "$hit" =~ $include_line ]] || continue
        file="${BASH_REMATCH[1]}"
        line="${BASH_REMATCH[2]}"
        target="${BASH_REMATCH[3]}"
        relative="${file#"$root"/}"
        from_part="${relative%%/*}"
        from_rest="${relative#*/}"
        from_folder="${from_rest%%/*}"
        to_part="${target%%/*}"
        to_rest="${target#*/}"
        to_folder="${to_rest%%/*}"
        [[ -n "${part_rank[$to_part]:-}" ]] || continue
        if ((part_rank[$to_part] > part_rank[$from_part])); then
            complain "$relative:$line: $from_part/ includes $target: $to_part/ is above $from_part/"
            continue
        fi
        [[ "$to_part" == "$from_part" ]] || continue
        from_rank="${layer_rank[$from_part/$from_folder]:-}"
        to_rank="${layer_rank[$to_part/$to_folder]:-}"
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
