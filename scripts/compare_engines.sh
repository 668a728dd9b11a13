#!/usr/bin/env bash
# The scale benchmark on an older commit and on this tree, side by side: builds OLD_REV in a
# temporary git worktree (its own build folder, only what the benchmark needs), then runs
# every sample/count case on the old build and on this one in turn (the order swapped from
# one case to the next, so that a slower machine later on weighs on both alike) and writes
# one CSV with a label column: old-<rev> and new.
#
#   scripts/compare_engines.sh OLD_REV [--samples 1,5] [--counts 3000,30000] [--end-time-s S]
#                              [--set key=value]... [--threads N] [--full] [--out DIR]
#
# The options are sedem_bench_scale's (defaults: samples 1-5; counts 3000,30000,100000, and
# 1000000 with --full; the scene's end time). Output: DIR/compare_engines.csv (default
# DIR: out/compare-<rev>), and each run's own folder under DIR/runs.
#
# When OLD_REV has no sedem_bench_scale, the old side is `sedem run` of each sample with the
# same keys (frames, particle and field files off), read back from its run.json (wall time,
# steps, particle-steps/s, peak memory, each test's error; needs jq); the columns run.json
# does not hold (sample build time, list builds, engine bytes) are left empty.
#
# This tree's build/ is used for the new side (sedem_bench_scale is built there first).
# Environment: OLD_TREE=DIR uses a checkout of OLD_REV that is already there (its build/ is
# brought up to date) instead of a temporary worktree; CMAKE_CXX_COMPILER_LAUNCHER=ccache (and CCACHE_*) speed up the old build (the
# worktree goes under $TMPDIR: keep it below CCACHE_BASEDIR for cache hits);
# JOBS sets the build's parallelism (default: 2).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"

usage() { sed -n '2,23p' "$0" | sed 's/^# \{0,1\}//'; }
if [ $# -lt 1 ] || [ "$1" = "-h" ] || [ "$1" = "--help" ]; then usage; exit 0; fi
old_rev="$1"
shift

samples="1,2,3,4,5"
counts=""
full=false
out=""
common=()  # options passed to both sides' benchmark as they are
sets=()    # --set keys, also for the old `sedem run`
end_time=""
threads=""
while [ $# -gt 0 ]; do
  case "$1" in
    --samples) samples="$2"; shift 2 ;;
    --counts) counts="$2"; shift 2 ;;
    --full) full=true; shift ;;
    --out) out="$2"; shift 2 ;;
    --end-time-s) end_time="$2"; common+=(--end-time-s "$2"); shift 2 ;;
    --threads) threads="$2"; common+=(--threads "$2"); shift 2 ;;
    --set) sets+=("$2"); common+=(--set "$2"); shift 2 ;;
    --label) echo "compare_engines.sh: the labels are old-<rev> and new; --label ignored" >&2
      shift 2 ;;
    *) echo "compare_engines.sh: unknown option $1 (see --help)" >&2; exit 1 ;;
  esac
done
if [ -z "$counts" ]; then
  counts="3000,30000,100000"
  if $full; then counts="$counts,1000000"; fi
elif $full; then
  counts="$counts,1000000"
fi

old_sha="$(git rev-parse --verify "$old_rev^{commit}")"
old_short="$(git rev-parse --short "$old_sha")"
old_label="old-$old_short"
new_label="new"
[ -n "$out" ] || out="out/compare-$old_short"
mkdir -p "$out/runs"
out="$(cd "$out" && pwd)"
csv="$out/compare_engines.csv"
jobs="${JOBS:-2}"

# The old commit in a temporary worktree, removed on exit (or in OLD_TREE, kept).
tmp="$(mktemp -d "${TMPDIR:-/tmp}/sedem-compare.XXXXXX")"
old_tree="$tmp/old"
cleanup() {
  [ -n "${OLD_TREE:-}" ] || git -C "$root" worktree remove --force "$old_tree" >/dev/null 2>&1 || true
  rm -rf "$tmp"
}
trap cleanup EXIT
if [ -n "${OLD_TREE:-}" ]; then
  old_tree="$(cd "$OLD_TREE" && pwd)"
  if [ "$(git -C "$old_tree" rev-parse HEAD)" != "$old_sha" ]; then
    echo "compare_engines.sh: OLD_TREE $old_tree is not at $old_short" >&2
    exit 1
  fi
else
  git worktree add --detach "$old_tree" "$old_sha" >/dev/null
fi
echo "compare_engines.sh: building $old_short in $old_tree" >&2
if grep -q "sedem_bench_scale" "$old_tree/bench/CMakeLists.txt" 2>/dev/null; then
  old_kind=bench
  old_target=sedem_bench_scale
else
  old_kind=run
  old_target=sedem
  command -v jq >/dev/null || { echo "compare_engines.sh: the old side needs jq" >&2; exit 1; }
  echo "compare_engines.sh: $old_short has no sedem_bench_scale; its side is \`sedem run\`" >&2
fi
cmake -S "$old_tree" -B "$old_tree/build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DSEDEM_WERROR=OFF >/dev/null
cmake --build "$old_tree/build" --target "$old_target" --parallel "$jobs"

echo "compare_engines.sh: building sedem_bench_scale in $root/build" >&2
[ -f build/build.ninja ] || cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target sedem_bench_scale --parallel "$jobs"
new_bench="$root/build/bench/sedem_bench_scale"

parts=()
# Rewrites the comparison's CSV from every run's bench_scale.csv so far: under the header with
# the most columns, the rows of a build with fewer (an older one: new columns come last)
# padded with empty cells. Rewritten after each run, so an interrupted comparison keeps what
# it measured.
append_csv() {
  local file="$1"
  [ -f "$file" ] || return 0
  parts+=("$file")
  /usr/bin/python3 - "$csv" "${parts[@]}" <<'PY'
import csv, sys
out, files = sys.argv[1], sys.argv[2:]
tables = [list(csv.reader(open(f, newline=""))) for f in files]
header = max((t[0] for t in tables if t), key=len)
with open(out, "w", newline="") as f:
    w = csv.writer(f, lineterminator="\n")
    w.writerow(header)
    for t in tables:
        for row in t[1:]:
            w.writerow(row + [""] * (len(header) - len(row)))
PY
}

# One case on the old `sedem run`, written as a bench_scale.csv row.
run_old_sedem() {
  local sample="$1" count="$2" dir="$3"
  local args=(run "$old_tree/scenes/sample$sample.toml" --out "$dir" --quiet
    --set output.frames=false --set output.particles=false --set output.fields=false
    --set "sample.simulated_count=$count")
  [ -z "$end_time" ] || args+=(--set "run.end_time_s=$end_time")
  [ -z "$threads" ] || args+=(--set "integrator.threads=$threads")
  local s
  for s in "${sets[@]+"${sets[@]}"}"; do args+=(--set "$s"); done
  "$old_tree/build/app/sedem" "${args[@]}" || true
  local json="$dir/run.json"
  [ -f "$json" ] || return 0
  {
    echo "label,sample,status,requested_count,particles,threads,end_time_s,simulated_s,wall_s,sample_build_s,cpu_s,steps,particle_steps,particle_steps_per_s,list_builds,engine_peak_bytes,engine_bytes_per_particle,process_rss_start_bytes,process_peak_rss_bytes,process_peak_rss_per_run,error_hydrometer_pp,error_buoyancy_pp,error_pipette_pp,merit_particle_s_per_wall_s,sets,message"
    jq -r --arg lab "$old_label" --arg count "$count" --arg sets "${sets[*]-}" '
      def err(t): (.results[t].error_pp // "nan");
      [ $lab, (.scene.name // ""), (if .status == "complete" then "ok" else .status end),
        $count, .particle_count, "",
        (.scene["run.end_time_s"] // ""), .simulated_time_s, .wall_time_s, "", "", .steps,
        (.particle_steps_per_s * .wall_time_s), .particle_steps_per_s, "", "", "", "",
        .peak_memory_bytes, 1, err("hydrometer"), err("buoyancy"), err("pipette"),
        (if .wall_time_s > 0 then .particle_count * .simulated_time_s / .wall_time_s else 0 end),
        ($sets | gsub(","; " ")),
        ((.message // "") | gsub("[,\n]"; " ")) ] | @csv' "$json" | tr -d '"'
  } >"$dir/bench_scale.csv" || {
    echo "compare_engines.sh: cannot read $json" >&2
    rm -f "$dir/bench_scale.csv"
    return 0
  }
  tail -n 1 "$dir/bench_scale.csv"
}

run_case() {  # side sample count
  local side="$1" sample="$2" count="$3"
  local dir="$out/runs/$side-sample$sample-$count"
  rm -rf "$dir"
  mkdir -p "$dir"
  if [ "$side" = new ]; then
    "$new_bench" --samples "$sample" --counts "$count" --label "$new_label" --out "$dir" \
      "${common[@]+"${common[@]}"}" || true
  elif [ "$old_kind" = bench ]; then
    "$old_tree/build/bench/sedem_bench_scale" --samples "$sample" --counts "$count" \
      --label "$old_label" --out "$dir" "${common[@]+"${common[@]}"}" || true
  else
    run_old_sedem "$sample" "$count" "$dir"
  fi
  append_csv "$dir/bench_scale.csv"
}

rm -f "$csv"
k=0
IFS=',' read -r -a sample_list <<<"$samples"
IFS=',' read -r -a count_list <<<"$counts"
for sample in "${sample_list[@]}"; do
  for count in "${count_list[@]}"; do
    if [ $((k % 2)) -eq 0 ]; then order="old new"; else order="new old"; fi
    for side in $order; do run_case "$side" "$sample" "$count"; done
    k=$((k + 1))
  done
done
echo "compare_engines.sh: wrote $csv" >&2
