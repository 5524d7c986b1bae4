#!/usr/bin/env bash
# Rolling-shutter readout sweep on fr1_xyz (docs/slam.md, "Rolling shutter"): for each readout,
# ATE of a run on the first half alone (frames 0-121: where the built-in 25 ms was chosen), of
# the whole run, and of the whole run's second half (frames 122-243, aligned on their own: data
# the choice did not see). Every run deterministic with --dynamic off; prints Markdown.
# Usage: scripts/readout_sweep.sh [BUILD_DIR] [OUT_DIR] [READOUTS_MS...]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
out=${2:-/tmp/dynanav_readout_sweep}
shift $(($# < 2 ? $# : 2))
readouts=("$@")
[[ ${#readouts[@]} -gt 0 ]] || readouts=(0 5 10 15 20 25 30 35)
cli="$build/bin/dynanav"
seq=../shared/data/rgbd_dataset_freiburg1_xyz
[[ -x "$cli" ]] || { echo "no $cli: build first" >&2; exit 2; }
[[ -d "$seq" ]] || { echo "no $seq" >&2; exit 2; }
mkdir -p "$out"
ate() { "$cli" eval --gt "$seq/groundtruth.txt" --est "$1" | awk '/^ATE/ {print $3}'; }
half=122
split_stamp=$(grep -v '^#' "$seq/associations.txt" | sed -n "$((half + 1))p" | awk '{print $1}')
echo "| readout (ms) | first half, run alone | whole run | second half of the whole run |"
echo "|---|---|---|---|"
for ms in "${readouts[@]}"; do
  printf 'tracking:\n  rolling_shutter_readout_ms: %s\n' "$ms" > "$out/readout_$ms.yaml"
  common=(--dynamic off --deterministic --quiet --config "$out/readout_$ms.yaml")
  "$cli" run "$seq" --out "$out/first_$ms" --max-frames "$half" "${common[@]}"
  "$cli" run "$seq" --out "$out/whole_$ms" "${common[@]}"
  awk -v t="$split_stamp" '/^#/ || $1 >= t' "$out/whole_$ms/trajectory.txt" > "$out/second_$ms.txt"
  echo "| $ms | $(ate "$out/first_$ms/trajectory.txt") | $(ate "$out/whole_$ms/trajectory.txt") | $(ate "$out/second_$ms.txt") |"
done
