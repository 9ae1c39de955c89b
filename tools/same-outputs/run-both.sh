#!/usr/bin/env bash
# Runs the before/after set of a change that must not move a result, with two builds of bowwave, and
# compares every output (compare.py beside this file). BEFORE and AFTER are the two binaries; WORK a scratch
# folder. From the project's root:
#
#   tools/same-outputs/run-both.sh /tmp/before/bowwave target/release/bowwave /tmp/same-outputs
#
# What it runs with each (about 15 min on 2 cores): `validate` of every built-in case at resolution 20 and
# tank-3d at 10 (the printed tables and the written series and plots), a coarse `twodt` run with VTK frames,
# a coarse two-case study, the 3D slab at H/dx 10, the wedge at dx/L 2e-3, Athena Fr 0.64 at dx/L 7e-4 to
# its plunge, and (AFTER only) the coarse twodt run halted part-way and resumed on another thread count,
# against BEFORE's uninterrupted run. The study files differ in form between builds that changed the
# study-file schema: set OLD_STUDY_SCHEMA=1 when BEFORE reads `[stop]`/`[outputs]` instead of `[config]`.
set -euo pipefail
before=$(realpath "$1"); after=$(realpath "$2"); work=$3
root=$(pwd)
hull=$root/hulls/athena.csv
mkdir -p "$work"
run_set() {
    local bin=$1 out=$2 schema=$3
    rm -rf "$out" && mkdir -p "$out"
    for c in hydrostatic dam-break dam-break-mm elliptic-drop oscillating-drop jet-wall jet-plate jet-floor; do
        "$bin" validate "$c" --res 20 --out "$out/validate" 2>&1 | grep -v ": started\|: finished at\|: stopped early" > "$out/validate_$c.txt" || true
    done
    "$bin" validate tank-3d --res 10 --out "$out/validate" 2>&1 | grep -v ": started\|: finished at" > "$out/validate_tank-3d.txt" || true
    "$bin" twodt --hull "$hull" --fr 0.64 --dx 2.5e-3 --until 0.15 --output-dx 0.02 --out "$out/twodt" -q --vtk > /dev/null
    if [ "$schema" = old ]; then
        printf 'name = "coarse"\nhull = "%s"\nfroude = [0.5, 0.64]\n[resolution]\ndx = [3e-3, 3e-3]\n[stop]\nuntil = 0.15\ngive_up_at = 0.15\n[outputs]\noutput_dx = 0.02\n' "$hull" > "$out/coarse.toml"
    else
        printf 'name = "coarse"\nhull = "%s"\nfroude = [0.5, 0.64]\n[resolution]\ndx = [3e-3, 3e-3]\n[config]\nuntil = 0.15\ngive_up_at = 0.15\noutput_dx = 0.02\n' "$hull" > "$out/coarse.toml"
    fi
    "$bin" study "$out/coarse.toml" --out "$out/study" -q > /dev/null
    rm -f "$out/coarse.toml"
    "$bin" slab --res 10 --end 3 --out "$out/slab" -q | grep -v "particle-steps\|written" > "$out/slab.txt"
    "$bin" wedge --dx 2e-3 > "$out/wedge.txt"
    "$bin" twodt --hull "$hull" --fr 0.64 --dx 7e-4 --give-up-at 0.6 --out "$out/plunge" -q | grep -v "wall\|outputs in" > "$out/plunge.txt"
}
schema_before=new
[ "${OLD_STUDY_SCHEMA:-}" = 1 ] && schema_before=old
run_set "$before" "$work/before" "$schema_before"
run_set "$after" "$work/after" new
# A resumed run: halted part-way on one thread, gone on with two.
res=$work/after-resumed
rm -rf "$res"
"$after" --threads 1 twodt --hull "$hull" --fr 0.64 --dx 2.5e-3 --until 0.15 --output-dx 0.02 --out "$res" -q --vtk --wall-limit 0.1 || true
"$after" --threads 2 twodt --hull "$hull" --fr 0.64 --dx 2.5e-3 --until 0.15 --output-dx 0.02 --out "$res" -q --vtk > /dev/null
flag=""
[ "$schema_before" = old ] && flag=--config-format-changed
python3 tools/same-outputs/compare.py "$work/before" "$work/after" $flag | tail -1
python3 tools/same-outputs/compare.py "$work/before/twodt" "$res" | tail -1
