#!/usr/bin/env bash
# Issue 7's results table, every row run and evaluated by the project's own commands, each row
# deterministic and as the median of 3 real-time runs: Bonn crowd (dnn, geometry only, dynamics
# off), fr1_xyz (dynamics on / off) and the simulated office, pushed-box and standing scenes with
# ground-truth masks, clean and noisy; then the moving-flag scores of the deterministic sim runs.
# Prints Markdown; outputs stay in OUT_DIR.
# Usage: scripts/dynamic_results.sh [BUILD_DIR] [OUT_DIR]   (needs ../shared/data for the real rows)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
out=${2:-/tmp/dynanav_dynamic_results}
cli="$build/bin/dynanav"
data=../shared/data
[[ -x "$cli" ]] || { echo "no $cli: build first (scripts/test.sh or cmake --build --preset release)" >&2; exit 2; }
mkdir -p "$out"

ate() {  # ate SEQ RUN_DIR -> "rmse tracked/total"
  "$cli" eval --gt "$1/groundtruth.txt" --est "$2/trajectory.txt" --sequence "$1" |
    awk '/^ATE/ {a=$3} /^coverage/ {c=$2} END {print a, c}'
}
flags() {  # flags SEQ RUN_DIR CLASS_REGEX -> precision/recall of each such object that moved in view
  "$cli" eval --gt "$1/groundtruth.txt" --est "$2/trajectory.txt" --sequence "$1" --stats "$2/stats.json" |
    awk -v cls="$3" '$3 ~ cls && $8 != "nan" {printf "%s%s %s P %s R %s", sep, $3, $4, $6, $8; sep="; "}'
}
row() {  # row LABEL SEQ NAME [run args...]: the deterministic run, then 3 real-time runs
  local label=$1 seq=$2 name=$3; shift 3
  "$cli" run "$seq" --out "$out/$name" --quiet --deterministic "$@"
  local rmse tracked v t values=() tracked_rt=()
  read -r rmse tracked < <(ate "$seq" "$out/$name")
  for k in 1 2 3; do
    "$cli" run "$seq" --out "$out/$name.rt$k" --quiet --realtime "$@"
    read -r v t < <(ate "$seq" "$out/$name.rt$k")
    values+=("$v")
    tracked_rt+=("$t")
  done
  local sorted
  sorted=$(printf '%s\n' "${values[@]}" | sort -g | tr '\n' ' ')
  echo "| $label | \`${*}\` | $rmse | $tracked | $(echo "$sorted" | awk '{print $2}') (${sorted% }) | ${tracked_rt[*]} |"
}

echo "| sequence | dynanav run flags | ATE RMSE (m), --deterministic | tracked | --realtime: median of 3 (sorted runs) | tracked |"
echo "|---|---|---|---|---|---|"
bonn="$data/rgbd_bonn_crowd"
fr1="$data/rgbd_dataset_freiburg1_xyz"
if [[ -d "$bonn" ]]; then
  row "Bonn crowd" "$bonn" bonn_dnn --segmenter dnn
  row "Bonn crowd" "$bonn" bonn_none --segmenter none
  row "Bonn crowd" "$bonn" bonn_off --dynamic off
fi
if [[ -d "$fr1" ]]; then
  row "fr1_xyz" "$fr1" fr1_dnn --segmenter dnn
  row "fr1_xyz" "$fr1" fr1_off --dynamic off
fi

printf 'perception: {mask_noise_grow_px: 5, mask_noise_drop_share: 0.2}\n' > "$out/dilate5_drop20.yaml"
printf 'perception: {mask_noise_grow_px: -5, mask_noise_drop_share: 0.2}\n' > "$out/erode5_drop20.yaml"
moving=()
for scene in office pushed-box standing; do
  sim="$out/sim_$scene"
  [[ -f "$sim/objects_gt.jsonl" ]] || "$cli" simulate --scenario "$scene" --out "$sim" --frames 300 --seed 1 >/dev/null
  row "sim $scene" "$sim" "${scene}_masks" --segmenter masks
  moving+=("sim $scene, masks: $(flags "$sim" "$out/${scene}_masks" '^(box|person)$')")
  [[ $scene == standing ]] && continue
  for noise in dilate5_drop20 erode5_drop20; do
    row "sim $scene ($noise)" "$sim" "${scene}_$noise" --segmenter masks --config "$out/$noise.yaml"
    moving+=("sim $scene, $noise: $(flags "$sim" "$out/${scene}_$noise" '^(box|person)$')")
  done
done
echo
echo "Moving flags, deterministic runs (dynanav eval --stats; frames where the object shows < 1 % of"
echo "the image are not scored):"
printf -- '- %s\n' "${moving[@]}"
