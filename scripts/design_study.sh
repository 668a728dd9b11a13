#!/usr/bin/env bash
# The "Recommended variations" of docs/validation.md: `sedem design` for every sample and
# test (the reference search, then a DEM run that confirms it), and the table regenerated
# between the report's `generated:begin designs` markers.
#
#   scripts/design_study.sh [--dem-count N] [--set key=value]... [--out DIR] [--samples "1 2"]
#                           [--report-only] [--sedem EXE] [--doc FILE]
#
# Defaults: a DEM run of 1 000 000 particles with forces.suspension_contacts = false (about
# 25 s each, two when the designed depth differs from the standard's), into out/design.
set -euo pipefail
cd "$(dirname "$0")/.."

dem_count=1000000
sets=(--set forces.suspension_contacts=false)
out=out/design
samples="1 2 3 4 5"
sedem=build/app/sedem
doc=docs/validation.md
report_only=false
while [ $# -gt 0 ]; do
  case "$1" in
    --dem-count) dem_count="$2"; shift 2 ;;
    --set) sets+=(--set "$2"); shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --samples) samples="$2"; shift 2 ;;
    --report-only) report_only=true; shift ;;
    --sedem) sedem="$2"; shift 2 ;;
    --doc) doc="$2"; shift 2 ;;
    -h|--help) sed -n '2,10p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "design_study.sh: unknown option $1 (see --help)" >&2; exit 1 ;;
  esac
done

if [ "$report_only" = false ]; then
  [ -x "$sedem" ] || { echo "design_study.sh: $sedem not found; build it: ninja -C build sedem" >&2; exit 1; }
  for k in $samples; do
    for t in hydrometer buoyancy pipette; do
      echo "design_study.sh: sample$k $t"
      "$sedem" design "scenes/sample$k.toml" --test "$t" --dem-count "$dem_count" "${sets[@]}" \
        --out "$out/sample${k}_$t" --quiet
    done
  done
fi
python3 scripts/design_table.py "$out" "$doc"
