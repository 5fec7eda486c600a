#!/usr/bin/env bash
# Regenerates the seed corpora in tests/fuzz/corpus/<target>/ from the bundled programs and machine
# folders. The first byte of an evaluator or machine-folder input picks the machine or the file
# (see fuzz_evaluator.cpp and fuzz_machine_folder.cpp). Inputs that the fuzzers found and that
# regression tests cover are kept in corpus/<target>/found-*; this script leaves them alone.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."

corpus=tests/fuzz/corpus
machines=resources/machines
for target in parser evaluator machine-folder; do
    mkdir -p "$corpus/$target"
    find "$corpus/$target" -name 'seed-*' -delete
done

# seed FILE TARGET NAME [PREFIX]: the file's bytes, after PREFIX (the selector byte) if given.
seed() {
    { printf '%s' "${4:-}"; cat "$1"; } > "$corpus/$2/seed-$3"
}

for dir in tests/golden/*/; do
    name=$(basename "$dir")
    [[ -f "$dir/input.nc" ]] || continue
    seed "$dir/input.nc" parser "$name.nc"
    machine=0 # m350-linear16
    [[ "$name" == fanuc-* ]] && machine=1 # fanuc-ts27r
    seed "$dir/input.nc" evaluator "$name.nc" "$machine"
done
# the differential programs are FANUC programs of the positioning codes (G10, G52, G68, G54.1 ...)
for program in tests/diff/programs/*.nc; do
    name=diff-$(basename "$program")
    seed "$program" parser "$name"
    seed "$program" evaluator "$name" 1 # fanuc-ts27r
done
for program in "$machines"/*/slib-*.nc "$machines"/*/T.nc "$machines"/fanuc-*/*.nc; do
    name=$(basename "$(dirname "$program")")-$(basename "$program")
    seed "$program" parser "$name"
done

# The machine-folder selector: 0 machine.toml, 1 params.toml, 2 offsets.toml, 3 variables.toml,
# 4 tool.tbl, 5 toollife.txt, 6 spindle-load.toml, 7 modbus.toml (m350 folder for 0-2 and 7,
# fanuc-ts27r for 3-6), 8 machine.toml and 9 params.toml of the FANUC folder.
for folder in "$machines"/*/; do
    machine=$(basename "$folder")
    fanuc=0
    [[ "$machine" == fanuc-* ]] && fanuc=1
    for file in machine.toml params.toml; do
        [[ -f "$folder/$file" ]] || continue
        if [[ "$file" == machine.toml ]]; then selector=$((fanuc ? 8 : 0)); else selector=$((fanuc ? 9 : 1)); fi
        seed "$folder/$file" machine-folder "$machine-$file" "$selector"
    done
    for pair in 2:offsets.toml 3:variables.toml 4:tool.tbl 6:spindle-load.toml; do
        file=${pair#*:}
        [[ -f "$folder/$file" ]] && seed "$folder/$file" machine-folder "$machine-$file" "${pair%%:*}"
    done
done
printf '5; tool life groups\ngs 1\nignore 100\nltm count\ngroup 1 life 100 count\ntool 12 h 12 d 32 used 5\ntool 13 h 13 d 33\ngroup 2 life 30 minutes\ntool 4 used 7\n' \
    > "$corpus/machine-folder/seed-toollife.txt"
printf '7[slave.1.holding]\n8192 = 0\n8193 = 5000\n[slave.1.input]\n0 = 258\n[slave.2.coils]\n0 = 1\n1 = false\n[slave.2.discrete]\n7 = true\n' \
    > "$corpus/machine-folder/seed-modbus.toml"

# The bundled machines share hook files (M3.nc ...): one copy of each content is enough.
for target in parser evaluator machine-folder; do
    find "$corpus/$target" -name 'seed-*' -type f -print0 | xargs -0 md5sum | sort | awk 'seen[$1]++ { print $2 }' |
        xargs -r rm --
    echo "$target: $(find "$corpus/$target" -type f | wc -l) inputs"
done
