#!/usr/bin/env bash
# Issue 12's figures, measured by the project's own commands: a sequence (default the Bonn crowd
# window) with a segmenter (default dnn) run once deterministic and N times in each real-time
# mode (--realtime paced at the camera's 30 Hz; --realtime --unpaced), each run evaluated with
# `dynanav eval` (ATE over the processed frames, coverage). Prints one Markdown row per run and
# the medians. Outputs stay in OUT_DIR. Say what else ran on the machine when you quote it.
# Usage: scripts/realtime_results.sh [BUILD_DIR] [OUT_DIR] [RUNS] [SEQ_DIR] [run flags...]
set -euo pipefail
default_out=/tmp/dynanav_realtime_results default_count=5
source "$(dirname "$0")/lib/sequence_bench_args.sh"
runs=$count

row() {  # row NAME MODE_FLAGS...: one run, one Markdown row; the figures also go to $out/NAME.row
  local name=$1; shift
  "$cli" run "$seq" --out "$out/$name" --quiet "${flags[@]}" "$@"
  local ate tracked
  read -r ate tracked < <("$cli" eval --gt "$seq/groundtruth.txt" --est "$out/$name/trajectory.txt" --sequence "$seq" |
    awk '/^ATE/ {a=$3} /^coverage/ {c=$2} END {print a, c}')
  python3 - "$out/$name/stats.json" "$name" "$ate" "$tracked" <<'PY' | tee "$out/$name.row"
import json, sys
s = json.load(open(sys.argv[1])); st = s["stage_ms"]
seg = st.get("segmenter_thread", st.get("segmentation", {"count": 0, "mean": 0, "cpu_mean": 0}))
print(f"| {sys.argv[2]} | {s['fps']:.1f} | {s['frames']} | {s['dropped']} ({100*s['dropped_share']:.1f} %) | "
      f"{s['latency_ms']['mean']:.0f} / {s['latency_ms']['p95']:.0f} / {s['latency_ms']['max']:.0f} | "
      f"{1000*s['cpu_s']/max(1,s['frames']):.0f} | {seg['count']} × {seg['mean']:.0f} ms ({seg['cpu_mean']:.0f} CPU) | "
      f"{sys.argv[3]} | {sys.argv[4]} |")
PY
}

echo "sequence $seq, flags ${flags[*]}; load before: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "| run | frames/s | processed | dropped | latency mean / p95 / max (ms) | CPU ms per processed frame | segmentations × wall (thread CPU) | ATE RMSE (m) | tracked |"
echo "|---|---|---|---|---|---|---|---|---|"
row deterministic --deterministic
for k in $(seq 1 "$runs"); do row "paced$k" --realtime; done
for k in $(seq 1 "$runs"); do row "unpaced$k" --realtime --unpaced; done
python3 - "$out" "$runs" <<'PY'
import statistics, sys
out, runs = sys.argv[1], int(sys.argv[2])
for mode in ("paced", "unpaced"):
    rows = [open(f"{out}/{mode}{k}.row").read().split("|") for k in range(1, runs + 1)]
    col = lambda i: statistics.median(float(r[i].split()[0]) for r in rows)
    print(f"median of {runs} {mode}: {col(2):.1f} frames/s, dropped {statistics.median(int(r[4].split()[0]) for r in rows)}, "
          f"latency p95 {statistics.median(float(r[5].split('/')[1]) for r in rows):.0f} ms, ATE {col(8):.4f} m")
PY
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
