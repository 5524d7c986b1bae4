#!/usr/bin/env bash
# Issue 18's online rolling-shutter readout estimate against the simulator's true readout.
# For each scene, seed and true readout: simulate with `--rolling-shutter-ms R` (and a 10 ms
# exposure), then run with `--dynamic off --deterministic` three ways:
#   global  - tracking.rolling_shutter_readout_ms: 0 (keypoints not re-timed); the estimate is
#             read off the residuals of a tracker that ignores the shutter,
#   online  - the same, plus tracking.rolling_shutter_online: true (re-timed with the estimate
#             once its standard error is below tracking.rolling_shutter_online_max_sigma_ms),
#   truth   - the readout from the simulator's camera.yaml.
# and prints stats.json `rolling_shutter` (estimate, standard error, frames used) with each run's
# ATE from `dynanav eval`. Prints Markdown; outputs stay in OUT_DIR.
# Usage: [SCENES="static-room head-turns"] [SEEDS="1 2 3"] [READOUTS="0 25"] \
#        scripts/readout_results.sh [BUILD_DIR] [OUT_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
out=${2:-/tmp/dynanav_readout}
cli="$build/bin/dynanav"
[[ -x "$cli" ]] || { echo "no $cli: build first (cmake --build --preset release)" >&2; exit 2; }
command -v jq >/dev/null || { echo "jq is needed (scripts/setup.sh installs it)" >&2; exit 2; }
mkdir -p "$out"
printf 'tracking:\n  rolling_shutter_readout_ms: 0\n' >"$out/global.yaml"
printf 'tracking:\n  rolling_shutter_readout_ms: 0\n  rolling_shutter_online: true\n' \
  >"$out/online.yaml"

ate() {  # ate SEQ RUN_DIR -> rmse
  "$cli" eval --gt "$1/groundtruth.txt" --est "$2/trajectory.txt" --sequence "$1" |
    awk '/^ATE/ {print $3}'
}
r2() { awk -v x="$1" 'BEGIN { if (x == "null" || x == "") print "-"; else printf "%.2f", x }'; }
estimate() {  # estimate RUN_DIR -> "estimate_ms sigma_ms frames online_ms stages"
  local e s f o n
  read -r e s f o n < <(jq -r '.rolling_shutter | "\(.estimate_ms) \(.sigma_ms) \(.frames) \(.online_readout_ms) \(.online_stages | length)"' "$1/stats.json")
  echo "$(r2 "$e") $(r2 "$s") $f $(r2 "$o") $n"
}
echo "| scene | seed | true readout (ms) | estimate while re-timing with 0 (ms) ± | estimate while re-timing with the truth (ms) ± | online: readout used at the end (ms), stages | ATE re-timing with 0 (m) | ATE online (m) | ATE true readout (m) |"
echo "|---|---|---|---|---|---|---|---|---|"
for scene in ${SCENES:-static-room head-turns}; do
  for seed in ${SEEDS:-1 2 3}; do
    for readout in ${READOUTS:-0 25}; do
      sim="$out/sim_${scene}_seed${seed}_rs${readout}"
      [[ -f "$sim/groundtruth.txt" ]] ||
        "$cli" simulate --scenario "$scene" --seed "$seed" --rolling-shutter-ms "$readout" \
          --exposure-ms 10 --out "$sim" >/dev/null
      declare -A rmse
      for mode in global online truth; do
        run="$out/${scene}_seed${seed}_rs${readout}_$mode"
        config=()
        [[ $mode != truth ]] && config=(--config "$out/$mode.yaml")
        "$cli" run "$sim" --out "$run" --quiet --deterministic --dynamic off "${config[@]}"
        rmse[$mode]=$(ate "$sim" "$run")
      done
      read -r g_est g_sigma _ _ _ < <(estimate "$out/${scene}_seed${seed}_rs${readout}_global")
      read -r t_est t_sigma _ _ _ < <(estimate "$out/${scene}_seed${seed}_rs${readout}_truth")
      read -r _ _ _ online stages < <(estimate "$out/${scene}_seed${seed}_rs${readout}_online")
      echo "| $scene | $seed | $readout | $g_est ± $g_sigma | $t_est ± $t_sigma | $online, $stages |" \
        "${rmse[global]} | ${rmse[online]} | ${rmse[truth]} |"
    done
  done
done
