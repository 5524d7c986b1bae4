#!/usr/bin/env bash
# What late masks cost, without threads or timing noise (issue 12): the sequence (default the
# Bonn crowd window) run --deterministic with perception.emulated_lag_frames = 0..MAX_LAG, i.e.
# each segmentation used LAG frames after its frame, carried there by chained flow, the next one
# starting there — what the real-time segmenter thread does when one call takes LAG frames.
# Prints one Markdown row per lag (ATE over every frame, evaluated with `dynanav eval`).
# Usage: scripts/lag_results.sh [BUILD_DIR] [OUT_DIR] [MAX_LAG] [SEQ_DIR] [run flags...]
set -euo pipefail
default_out=/tmp/dynanav_lag_results default_count=4
source "$(dirname "$0")/lib/sequence_bench_args.sh"
max_lag=$count
echo "sequence $seq, flags ${flags[*]} --deterministic"
echo "| segmentation lag (frames) | ATE RMSE (m) | max error (m) | tracked |"
echo "|---|---|---|---|"
for lag in $(seq 0 "$max_lag"); do
  printf 'perception:\n  emulated_lag_frames: %s\n' "$lag" > "$out/lag$lag.yaml"
  "$cli" run "$seq" --out "$out/lag$lag" --quiet --deterministic --config "$out/lag$lag.yaml" "${flags[@]}"
  "$cli" eval --gt "$seq/groundtruth.txt" --est "$out/lag$lag/trajectory.txt" --sequence "$seq" --json |
    python3 -c "import json,sys; r=json.load(sys.stdin); a=r['ate_m']; c=r['coverage']; print(f\"| $lag | {a['rmse']:.4f} | {a['max']:.3f} | {c['tracked_frames']}/{c['total_frames']} |\")"
done
