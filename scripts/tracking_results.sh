#!/usr/bin/env bash
# Object-tracking figures (docs/tracking.md): simulates crossing / approach / office (240 frames,
# seeds 1-3) and pushed-box (300 frames), runs them with --segmenter masks (clean, and noisy masks:
# dilate / erode 5 px, 20 % of instances dropped), and prints dynanav eval-objects' summary lines.
# Usage: scripts/tracking_results.sh [WORK_DIR]   (default /tmp/dynanav_tracking)
# EXTRA_CONFIG: YAML appended to every row's config (sections other than tracking and
# perception), e.g. EXTRA_CONFIG=$'objects:\n  gate_missed: false\n' for an A/B of one key.
set -euo pipefail
B=${DYNANAV:-$(dirname "$0")/../build/release/bin/dynanav}
W=${1:-/tmp/dynanav_tracking}
mkdir -p "$W"
# The 14 m approach hall leaves fewer than the default 500 keypoints with depth in its first
# frames (depth ends at 4.5 m): SLAM is allowed to start with 150 in every row of this table.
common='tracking:\n  init_min_depth_features: 150\n'
printf "$common" > "$W/clean.yaml"
for g in 5 -5; do
  printf "${common}perception:\n  mask_noise_grow_px: %s\n  mask_noise_drop_share: 0.2\n" "$g" > "$W/noisy$g.yaml"
done
for c in clean noisy5 noisy-5; do printf '%s' "${EXTRA_CONFIG:-}" >> "$W/$c.yaml"; done
row() {  # row SEQ CONFIG
  local out="$W/run_$(basename "$1")_$(basename "$2" .yaml)"
  "$B" run "$1" --out "$out" --segmenter masks --deterministic --quiet --config "$2" 2>/dev/null
  echo "## $(basename "$1") $(basename "$2" .yaml)"
  "$B" eval-objects --gt "$1/objects_gt.jsonl" --est "$out/objects.jsonl"
}
for scene in crossing approach office; do
  for seed in 1 2 3; do
    seq="$W/${scene}_$seed"
    [ -f "$seq/objects_gt.jsonl" ] || "$B" simulate --scenario $scene --out "$seq" --frames 240 --seed $seed >/dev/null
    row "$seq" "$W/clean.yaml"
  done
  row "$W/${scene}_1" "$W/noisy5.yaml"
  row "$W/${scene}_1" "$W/noisy-5.yaml"
done
seq="$W/pushed-box_1"
[ -f "$seq/objects_gt.jsonl" ] || "$B" simulate --scenario pushed-box --out "$seq" --frames 300 --seed 1 >/dev/null
for c in clean noisy5 noisy-5; do row "$seq" "$W/$c.yaml"; done
