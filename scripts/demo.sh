#!/usr/bin/env bash
# The demo for a fresh machine: installs dependencies, builds dynanav, simulates the `office`
# scene (three people walking while the wearer walks; exact ground truth), runs the whole system
# on it and prints a summary. Needs nothing outside this repository.
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

seq="$out/office"
echo "== simulating the office scene ($frames frames) into $seq"
"$cli" simulate --scenario office --out "$seq" --frames "$frames" --seed 1
echo "== running dynanav on it"
"$cli" run "$seq" --out "$out/run" --deterministic --all-outputs
echo "== accuracy against the simulator's ground truth"
"$cli" eval --gt "$seq/groundtruth.txt" --est "$out/run/trajectory.txt" --sequence "$seq"
echo "== summary (from $out/run/stats.json)"
grep -E '^  "(frames|tracked|lost|keyframes|map_points|fps|loops|relocalisations)"' "$out/run/stats.json" || true
echo "outputs: $out/run (trajectory.txt, keyframes.txt, stats.json, config_used.yaml); sequence: $seq"
echo "maps and pictures: $out/run/map.ply map.bt occupancy.png topview.png annotated.mp4 report.html (open report.html in a browser)"
