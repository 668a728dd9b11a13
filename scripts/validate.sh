#!/usr/bin/env bash
# The validation of docs/validation.md: runs the paper's five samples, draws the Figs. 11-18
# equivalents side by side, copies them into docs/validation/ and regenerates the report's
# tables (the parts of docs/validation.md between its "generated" markers).
#
#   scripts/validate.sh [--count N] [--end S] [--out DIR] [--reduce F] [--set key=value]...
#                       [--short] [--report-only] [--sedem EXE] [--report EXE] [--doc FILE]
#
# Defaults are the full validation: the scene files' 30 000 particles, the whole test
# (86 400 s). --short is a pipeline check of a few minutes: 120 particles in 30 sizes, 120 s,
# the hydrometer read at 0.5, 1, 1.5 and 2 min, the sphere and the pipette at 0.25, 0.5,
# 0.75, 1, 1.5 and 2 min. --set applies to every run. Besides the five runs it makes the
# same runs with F times fewer particles (default 4), those again with count weighting, and
# reads the five runs' particles again with the sphere and the pipette at several depths.
# --report-only skips the simulations and uses what --out holds.
#
#   scripts/validate.sh --study [--seeds N] [--count-passing N] [--count-contacts N]
#                       [--regimes passing,contacts] [--depth-regimes passing,contacts]
#                       [--count-depth N]
#                       [--jobs J] [--short] [--report-only]
#
# --study decides the paper's conclusions over seeds instead (docs/validation.md, "The
# conclusions over seeds"): per regime, the five samples --seeds times (default 10) and the same
# seeds with the sphere and the pipette at 0.1 and 0.7 H, into DIR/study/<regime>/{main,
# shallow,deep}; then the study section of the report. Regimes: "passing" (suspension contacts
# off, --count-passing particles, default 1 000 000) and "contacts" (contacts everywhere,
# --count-contacts, default 100 000). --depth-regimes: the regimes that also get the depth
# runs (default: every one; docs/validation.md's study gave them to "passing" only, at 100 000
# particles, as they double a regime's cost); --count-depth: their particle count (default:
# the regime's). --jobs: runs at a time (default: all cores). With --short: 120 particles,
# 120 s and 3 seeds, a pipeline check of a minute or two. --study also designs a schedule for
# every sample and test (scripts/design_study.sh, the "Recommended variations"), confirmed by a
# DEM run at --count-passing particles.
set -euo pipefail
cd "$(dirname "$0")/.."

count=30000
end=86400
out=out/validation
reduce=4
report_only=false
sedem=build/app/sedem
report=build/bench/sedem_validation_report
doc=docs/validation.md
sets=()
depths="0.1 0.2 0.3 0.5 0.7"
study=false
short=false
seeds=""
count_passing=""
count_contacts=""
regimes=passing,contacts
depth_regimes=passing,contacts
count_depth=""
jobs=$(nproc)

while [ $# -gt 0 ]; do
  case "$1" in
    --count) count="$2"; shift 2 ;;
    --end) end="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --reduce) reduce="$2"; shift 2 ;;
    --set) sets+=(--set "$2"); shift 2 ;;
    --study) study=true; shift ;;
    --seeds) seeds="$2"; shift 2 ;;
    --count-passing) count_passing="$2"; shift 2 ;;
    --count-contacts) count_contacts="$2"; shift 2 ;;
    --regimes) regimes="$2"; shift 2 ;;
    --depth-regimes) depth_regimes="$2"; shift 2 ;;
    --count-depth) count_depth="$2"; shift 2 ;;
    --jobs) jobs="$2"; shift 2 ;;
    --short)
      short=true; count=120; end=120
      sets+=(--set sample.size_count=30 --set "instruments.hydrometer.times_min=[0.5,1,1.5,2]"
        --set "instruments.buoyancy.times_min=[0.25,0.5,0.75,1,1.5,2]"
        --set "instruments.pipette.times_min=[0.25,0.5,0.75,1,1.5,2]")
      shift ;;
    --report-only) report_only=true; shift ;;
    --sedem) sedem="$2"; shift 2 ;;
    --report) report="$2"; shift 2 ;;
    --doc) doc="$2"; shift 2 ;;
    -h|--help) sed -n '2,26p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "validate.sh: unknown option $1 (see --help)" >&2; exit 1 ;;
  esac
done

for exe in "$sedem" "$report"; do
  if [ ! -x "$exe" ]; then
    echo "validate.sh: $exe not found; build it: ninja -C build sedem sedem_validation_report" >&2
    exit 1
  fi
done

mkdir -p "$out"
samples=(1 2 3 4 5)
scenes=()
for k in "${samples[@]}"; do scenes+=("scenes/sample$k.toml"); done
small=$(( count / reduce ))
# The early part of the test: its first hour, or the first quarter of a shorter run.
early=$(( end / 4 < 3600 ? end / 4 : 3600 ))
common=(--set "run.end_time_s=$end" ${sets[@]+"${sets[@]}"})
# Progress (simulated time, ETA) only on a terminal: in a log it is noise.
if [ ! -t 2 ]; then common+=(--quiet); fi
lean=(--set output.frames=false --set output.fields=false --set output.particles=false)

if [ "$study" = true ]; then
  # Written before the runs: the study's counts; --short keeps its pipeline check tiny.
  if [ "$short" = true ]; then
    seeds=${seeds:-3}; count_passing=${count_passing:-120}; count_contacts=${count_contacts:-120}
  fi
  seeds=${seeds:-10}; count_passing=${count_passing:-1000000}
  count_contacts=${count_contacts:-100000}
  IFS=, read -r -a regime_list <<< "$regimes"
  for r in "${regime_list[@]}"; do
    case "$r" in
      passing|contacts) ;;
      *) echo "validate.sh: unknown regime $r (passing, contacts)" >&2; exit 1 ;;
    esac
  done
  depth_count=0
  for r in "${regime_list[@]}"; do
    case ",$depth_regimes," in *",$r,"*) depth_count=$((depth_count + 1)) ;; esac
  done
  runs_total=$(( (${#regime_list[@]} + 2 * depth_count) * ${#scenes[@]} * seeds ))
  echo "validate.sh: study over $seeds seeds, regimes $regimes (depth runs: $depth_regimes):" \
    "$runs_total runs (${#scenes[@]} samples x $seeds seeds x main, shallow and deep batches)"
  regime_args=()
  for r in "${regime_list[@]}"; do
    dir="$out/study/$r"
    regime_args+=(--regime "$r=$dir")
    if [ "$report_only" = true ]; then continue; fi
    if [ "$r" = passing ]; then
      n=$count_passing; regime_sets=(--set forces.suspension_contacts=false)
    else
      n=$count_contacts; regime_sets=()
    fi
    study_common=("${scenes[@]}" --seeds "$seeds" --jobs "$jobs" --set "sample.simulated_count=$n"
      ${regime_sets[@]+"${regime_sets[@]}"} "${lean[@]}" "${common[@]}")
    echo "validate.sh: $r, $n particles -> $dir/main"
    "$sedem" batch "${study_common[@]}" --out "$dir/main" --overwrite ||
      echo "validate.sh: a run failed; the study leaves it out" >&2
    # The depth runs: only in the regimes asked for (each doubles a regime's cost), and only
    # as long as the sphere's and the pipette's last reading (480 min).
    case ",$depth_regimes," in *",$r,"*) ;; *) continue ;; esac
    depth_end=$(( end < 28800 ? end : 28800 ))
    for depth in shallow:0.1 deep:0.7; do
      echo "validate.sh: $r, sphere and pipette at ${depth#*:} H -> $dir/${depth%%:*}"
      "$sedem" batch "${study_common[@]}" --out "$dir/${depth%%:*}" --overwrite \
        --set "instruments.buoyancy.depth_fraction=${depth#*:}" \
        --set "instruments.pipette.depth_fraction=${depth#*:}" \
        --set instruments.hydrometer.enabled=false --set "run.end_time_s=$depth_end" \
        --set "sample.simulated_count=${count_depth:-$n}" ||
        echo "validate.sh: a run failed; the study leaves it out" >&2
    done
  done
  mkdir -p "$out/study"
  "$report" study "${regime_args[@]}" --out "$out/study" --early-s "$early" --update "$doc" |
    tee "$out/study/verdicts.txt"
  # The recommended variations: a designed schedule for every sample and test, confirmed by a
  # DEM run at the passing regime's count.
  design_args=(--dem-count "$count_passing" --out "$out/design" --sedem "$sedem" --doc "$doc")
  if [ "$report_only" = true ]; then design_args+=(--report-only); fi
  scripts/design_study.sh "${design_args[@]}"
  exit 0
fi

# A failed run is reported (its status shows in the report) rather than losing the others;
# Ctrl-C stops the whole validation.
batch() {
  local status=0
  # Each run replaces the one an earlier validation left in its folder.
  "$sedem" batch "$@" --overwrite || status=$?
  if [ "$status" -eq 130 ]; then exit 130; fi
  if [ "$status" -ne 0 ]; then echo "validate.sh: a run failed (exit $status); see run.json" >&2; fi
}

if [ "$report_only" = false ]; then
  echo "validate.sh: five samples, $count particles, $end s -> $out/runs"
  batch "${scenes[@]}" --out "$out/runs" --set "sample.simulated_count=$count" \
    "${common[@]}"
  echo "validate.sh: the same with $small particles -> $out/reduced"
  batch "${scenes[@]}" --out "$out/reduced" --set "sample.simulated_count=$small" \
    "${lean[@]}" "${common[@]}"
  echo "validate.sh: $small particles, count weighting -> $out/weighting"
  batch "${scenes[@]}" --out "$out/weighting" --set "sample.simulated_count=$small" \
    --set sample.weighting=uniform_count "${lean[@]}" "${common[@]}"
fi

echo "validate.sh: the five runs' particles read at depths $depths (x H) -> $out/depth"
depth_runs=()
for k in "${samples[@]}"; do
  for f in $depths; do
    dir="$out/depth/sample${k}_depth$f"
    if "$report" variant "$out/runs/sample$k" "$dir" \
      --set "instruments.buoyancy.depth_fraction=$f" --set "instruments.pipette.depth_fraction=$f" \
      --set instruments.hydrometer.enabled=false --set output.frames=false \
      --set output.fields=false && "$sedem" render "$dir" --quiet; then
      depth_runs+=("$dir")
    fi
  done
done

echo "validate.sh: figures side by side -> $out/figures and docs/validation/"
runs=() reduced=() weighting=()
for k in "${samples[@]}"; do
  runs+=("$out/runs/sample$k")
  reduced+=("$out/reduced/sample$k")
  weighting+=("$out/weighting/sample$k")
done
"$sedem" render "${runs[@]}" --out "$out/figures" --quiet ||
  echo "validate.sh: drawing the figures failed; the report goes on without new ones" >&2
mkdir -p docs/validation
for f in fig11_column fig12_largest_diameter fig13_bulb_density fig14_bulb_average \
  fig15_hydrometer fig16_buoyancy fig17_pipette fig18_granulometry; do
  if [ -f "$out/figures/$f.png" ]; then cp "$out/figures/$f.png" docs/validation/; fi
done

cores=$(nproc)
cpu=$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//' || true)
"$report" report --runs "${runs[@]}" --reduced "${reduced[@]}" --weighting "${weighting[@]}" \
  ${depth_runs[@]+--depth "${depth_runs[@]}"} --early-s "$early" --machine "$cores cores, ${cpu:-unknown CPU}" \
  --update "$doc" | tee "$out/verdicts.txt"
