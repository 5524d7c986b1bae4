#!/usr/bin/env bash
# Issue 18's false-dynamics figures on exact ground truth: simulates head-turns and
# head-turns-walkers (yaw up to 150 deg/s, nods, 25 ms rolling shutter, 10 ms exposure = motion
# blur), runs each with --dynamic off, --segmenter none and --segmenter masks (deterministic),
# evaluates ATE with `dynanav eval`, and counts the keypoints the dynamics flagged dynamic
# (stats.json dynamics.per_frame: dynamic_keypoints against dynamic + static keypoints).
# In head-turns nothing moves, so every flagged keypoint is a false dynamic. In
# head-turns-walkers with `masks` the people are cut out of extraction (so flagged keypoints are
# static ones too); with `none` the share also counts keypoints on the walkers (true movers), so
# it is an upper bound of the false share there.
# Prints Markdown; outputs stay in OUT_DIR. SEEDS (default "1") lists the simulator seeds: single
# runs of these scenes move by several percent with small changes, so judge a change on several.
# Usage: [SEEDS="1 2 3"] scripts/head_turn_results.sh [BUILD_DIR] [OUT_DIR] [extra run flags...]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
out=${2:-/tmp/dynanav_head_turns}
shift $(($# < 2 ? $# : 2))
extra=("$@")
cli="$build/bin/dynanav"
[[ -x "$cli" ]] || { echo "no $cli: build first (cmake --build --preset release)" >&2; exit 2; }
mkdir -p "$out"

ate() {  # ate SEQ RUN_DIR -> "rmse tracked/total"
  "$cli" eval --gt "$1/groundtruth.txt" --est "$2/trajectory.txt" --sequence "$1" |
    awk '/^ATE/ {a=$3} /^coverage/ {c=$2} END {print a, c}'
}
flagged() {  # flagged RUN_DIR -> "dynamic total share%" over the run ("-" with dynamics off)
  jq -r 'if (.dynamics.enabled | not) then "- - -" else
           (.dynamics.per_frame.dynamic_keypoints | add) as $d |
           (.dynamics.per_frame.static_keypoints | add) as $s |
           "\($d) \($d + $s) \(if $d + $s > 0 then 100 * $d / ($d + $s) * 1000 | round / 1000 else 0 end)"
         end' "$1/stats.json"
}

echo "| scene | seed | flags | ATE RMSE (m) | tracked | vs --dynamic off | keypoints flagged dynamic |"
echo "|---|---|---|---|---|---|---|"
for scene in head-turns head-turns-walkers; do
  for seed in ${SEEDS:-1}; do
    sim="$out/sim_${scene}_seed$seed"
    [[ -f "$sim/groundtruth.txt" ]] ||
      "$cli" simulate --scenario "$scene" --seed "$seed" --rolling-shutter-ms 25 --exposure-ms 10 \
        --out "$sim" >/dev/null
    off_rmse=""
    for mode in off none masks; do
      case $mode in
        off) args=(--dynamic off) ;;
        *) args=(--segmenter "$mode") ;;
      esac
      run="$out/${scene}_seed${seed}_$mode"
      "$cli" run "$sim" --out "$run" --quiet --deterministic "${args[@]}" "${extra[@]}"
      read -r rmse tracked < <(ate "$sim" "$run")
      read -r dyn total share < <(flagged "$run")
      [[ $mode == off ]] && off_rmse=$rmse
      rel=$(awk -v a="$rmse" -v b="$off_rmse" 'BEGIN {printf "%+.1f %%", 100 * (a - b) / b}')
      flags_text="-"
      [[ $dyn != "-" ]] && flags_text="$dyn of $total ($share %)"
      echo "| $scene | $seed | \`${args[*]} ${extra[*]}\` | $rmse | $tracked | $rel | $flags_text |"
    done
  done
done
