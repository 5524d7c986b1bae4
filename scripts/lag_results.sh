#!/usr/bin/env bash
# What late masks cost, without threads or timing noise (issue 12): the sequence (default the
# Bonn crowd window) run --deterministic with perception.emulated_lag_frames = 0..MAX_LAG, i.e.
# each segmentation used LAG frames after its frame, carried there by chained flow, the next one
# starting there — what the real-time segmenter thread does when one call takes LAG frames.
# Prints one Markdown row per lag (ATE over every frame, evaluated with `dynanav eval`).
# Usage: scripts/lag_results.sh [BUILD_DIR] [OUT_DIR] [MAX_LAG] [SEQ_DIR] [run flags...]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
out=${2:-/tmp/dynanav_lag_results}
max_lag=${3:-4}
seq=${4:-../shared/data/rgbd_bonn_crowd}
shift $(($# < 4 ? $# : 4))
flags=("$@")
[[ ${#flags[@]} -gt 0 ]] || flags=(--segmenter dnn)
cli="$build/bin/dynanav"
[[ -x "$cli" ]] || { echo "no $cli: build first (cmake --build --preset release)" >&2; exit 2; }
[[ -d "$seq" ]] || { echo "no sequence $seq" >&2; exit 2; }
mkdir -p "$out"
echo "sequence $seq, flags ${flags[*]} --deterministic"
echo "| segmentation lag (frames) | ATE RMSE (m) | max error (m) | tracked |"
echo "|---|---|---|---|"
for lag in $(seq 0 "$max_lag"); do
  printf 'perception:\n  emulated_lag_frames: %s\n' "$lag" > "$out/lag$lag.yaml"
  "$cli" run "$seq" --out "$out/lag$lag" --quiet --deterministic --config "$out/lag$lag.yaml" "${flags[@]}"
  "$cli" eval --gt "$seq/groundtruth.txt" --est "$out/lag$lag/trajectory.txt" --sequence "$seq" --json |
    python3 -c "import json,sys; r=json.load(sys.stdin); a=r['ate_m']; c=r['coverage']; print(f\"| $lag | {a['rmse']:.4f} | {a['max']:.3f} | {c['tracked_frames']}/{c['total_frames']} |\")"
done
