#!/usr/bin/env bash
# Object-tracking figures (docs/tracking.md): simulates crossing / approach / office /
# office-ramped (240 frames, seeds 1-3) and pushed-box (300 frames), runs them with --segmenter
# masks (clean, and noisy masks: dilate / erode 5 px, 20 % of instances dropped; office-ramped
# clean only), and prints dynanav eval-objects' summary lines.
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
sim_row() {  # sim_row SCENE SEED CONFIG
  local seq="$W/${1}_$2"
  [ -f "$seq/objects_gt.jsonl" ] || "$B" simulate --scenario "$1" --out "$seq" --frames 240 --seed "$2" >/dev/null
  row "$seq" "$3"
}
for scene in crossing approach office; do
  for seed in 1 2 3; do sim_row $scene $seed "$W/clean.yaml"; done
  row "$W/${scene}_1" "$W/noisy5.yaml"
  row "$W/${scene}_1" "$W/noisy-5.yaml"
done
# office's walkers start and stop within a frame; office-ramped's take 0.6 s, as people do.
for seed in 1 2 3; do sim_row office-ramped $seed "$W/clean.yaml"; done
seq="$W/pushed-box_1"
[ -f "$seq/objects_gt.jsonl" ] || "$B" simulate --scenario pushed-box --out "$seq" --frames 300 --seed 1 >/dev/null
for c in clean noisy5 noisy-5; do row "$seq" "$W/$c.yaml"; done
