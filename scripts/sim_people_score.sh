#!/usr/bin/env bash
# Person recall and mask IoU of the dnn segmenter on simulated scenes (docs/simulator.md,
# "People a detector sees"): simulate each scenario and seed, segment it, score it against the
# simulator's ground truth with `dynanav eval-masks`, print one line per run.
#   scripts/sim_people_score.sh [--models DIR] [--scenarios "office approach crossing"]
#                               [--seeds "1 2 3"] [--work DIR] [--bin build/release/bin/dynanav]
set -euo pipefail
bin=build/release/bin/dynanav
models=""
scenarios="office approach crossing"
seeds="1 2 3"
work=$(mktemp -d /tmp/sim_people.XXXXXX)
while [[ $# -gt 0 ]]; do
  case "$1" in
    --models) models=$2; shift 2 ;;
    --scenarios) scenarios=$2; shift 2 ;;
    --seeds) seeds=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    --bin) bin=$2; shift 2 ;;
    *) echo "sim_people_score: unknown option $1" >&2; exit 2 ;;
  esac
done
model_args=()
[[ -n "$models" ]] && model_args=(--models "$models")
mkdir -p "$work"
printf '%-10s %4s %7s %6s %7s %9s %9s\n' scenario seed scored found recall iou_found iou_all
for scenario in $scenarios; do
  for seed in $seeds; do
    sim="$work/$scenario-$seed"
    seg="$work/$scenario-$seed-seg"
    [[ -f "$sim/objects_gt.jsonl" ]] ||
      "$bin" simulate --scenario "$scenario" --seed "$seed" --out "$sim" > "$work/log.txt" 2>&1
    "$bin" segment "$sim" --out "$seg" --segmenter dnn --no-video "${model_args[@]}" \
      >> "$work/log.txt" 2>&1
    "$bin" eval-masks "$sim" "$seg" --json > "$seg/eval_masks.json"
    python3 - "$scenario" "$seed" "$seg/eval_masks.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[3]))
print('%-10s %4s %7d %6d %6.1f%% %9.3f %9.3f' % (sys.argv[1], sys.argv[2], d['scored'], d['found'],
      100 * d['recall'], d['median_iou_found'], d['median_iou_all']))
PY
  done
done
