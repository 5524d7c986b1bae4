#!/usr/bin/env bash
# Builds the libFuzzer targets (preset `fuzz`: clang, ASan + UBSan), makes a seed corpus and runs
# every fuzzer for SECONDS each. Seeds are generated here, never committed: the list files and
# ground truth of ../shared/data (first lines), and what dynanav itself writes for a small
# simulated sequence (camera.yaml, rgb.txt, groundtruth.txt, masks.json, mask PNGs,
# config_used.yaml, a tiny vocabulary). The corpus under build/fuzz/corpus/ grows from run to
# run. A finding (crash, sanitizer report, uncaught exception, timeout) leaves its input in
# build/fuzz/findings/ and fails the script.
# Usage: scripts/fuzz.sh [SECONDS=60] [FUZZER...]     e.g. scripts/fuzz.sh 300 fuzz_config
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
all=(fuzz_stamped_list fuzz_trajectory fuzz_camera_yaml fuzz_config fuzz_masks_json fuzz_mask_png
     fuzz_vocabulary)
fuzzers=("$@")
[ ${#fuzzers[@]} -gt 0 ] || fuzzers=("${all[@]}")

bash scripts/setup.sh >/dev/null
export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz
cli=build/release/bin/dynanav
if [ ! -x "$cli" ]; then
  cmake --preset release >/dev/null
  cmake --build --preset release --target dynanav_cli
fi

root=build/fuzz
seeds=$root/seeds
rm -rf "$seeds"
mkdir -p "$seeds" "$root/findings"
for f in "${all[@]}"; do mkdir -p "$seeds/$f" "$root/corpus/$f"; done

# Seeds from the real sequences (the first 60 lines keep each seed small and fast).
shared=../shared/data
if [ -d "$shared" ]; then
  for seq in "$shared"/*/; do
    name=$(basename "$seq")
    for list in rgb.txt depth.txt; do
      if [ -f "$seq/$list" ]; then head -n 60 "$seq/$list" >"$seeds/fuzz_stamped_list/${name}_$list"; fi
    done
    if [ -f "$seq/groundtruth.txt" ]; then
      head -n 60 "$seq/groundtruth.txt" >"$seeds/fuzz_trajectory/${name}_gt.txt"
    fi
  done
fi
# Seeds from dynanav's own outputs on a small simulated sequence.
sim=$root/seed_sim
rm -rf "$sim" "$root/seed_run"
"$cli" simulate --scenario crossing --frames 12 --out "$sim" >/dev/null 2>&1
"$cli" run "$sim" --out "$root/seed_run" --segmenter none --max-frames 12 --quiet >/dev/null 2>&1 || true
cp "$sim/rgb.txt" "$seeds/fuzz_stamped_list/sim_rgb.txt"
cp "$sim/groundtruth.txt" "$seeds/fuzz_trajectory/sim_gt.txt"
if [ -f "$root/seed_run/trajectory.txt" ]; then cp "$root/seed_run/trajectory.txt" "$seeds/fuzz_trajectory/run.txt"; fi
cp "$sim/camera.yaml" "$seeds/fuzz_camera_yaml/"
cp "$sim/masks.json" "$seeds/fuzz_masks_json/"
if [ -f "$root/seed_run/config_used.yaml" ]; then cp "$root/seed_run/config_used.yaml" "$seeds/fuzz_config/"; fi
printf 'orb:\n  n_features: 1500\nrun:\n  dynamic: false\n' >"$seeds/fuzz_config/small.yaml"
for png in $(ls "$sim"/masks/*.png | sed -n '1p;6p;12p'); do cp "$png" "$seeds/fuzz_mask_png/"; done
"$cli" vocabulary train "$sim/rgb" --k 3 --levels 2 --features 100 --out "$seeds/fuzz_vocabulary/tiny.dnvoc" >/dev/null 2>&1

declare -A max_len=([fuzz_mask_png]=65536 [fuzz_vocabulary]=16384)
status=0
printf '%-18s %8s %10s %8s %8s\n' fuzzer seconds execs execs/s corpus
for f in "${fuzzers[@]}"; do
  log=$root/$f.log
  set +e
  # -timeout: one input taking longer than 10 s is a hang; -rss_limit_mb: a memory blow-up.
  "$root/bin/$f" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -max_len="${max_len[$f]:-4096}" -print_final_stats=1 \
    -artifact_prefix="$root/findings/$f-" "$root/corpus/$f" "$seeds/$f" >"$log" 2>&1
  rc=$?
  set -e
  execs=$(grep -oP 'stat::number_of_executed_units:\s*\K\d+' "$log" || echo 0)
  rate=$(grep -oP 'stat::average_exec_per_sec:\s*\K\d+' "$log" || echo 0)
  corpus=$(ls "$root/corpus/$f" | wc -l)
  printf '%-18s %8s %10s %8s %8s\n' "$f" "$seconds" "$execs" "$rate" "$corpus"
  if [ $rc -ne 0 ]; then
    echo "FINDING in $f (exit $rc); input in $root/findings/, log $log:"
    grep -E "ERROR|SUMMARY|uncaught|deadly|Test unit written" "$log" | head -n 20
    status=1
  fi
done
if [ $status -eq 0 ]; then
  echo "fuzz: ${#fuzzers[@]} fuzzers, ${seconds} s each, no finding"
else
  echo "fuzz: FINDINGS (see above)"
fi
exit $status
