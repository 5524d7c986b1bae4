#!/usr/bin/env bash
# Trains the project's ORB vocabulary with our own tool, on images the project may redistribute:
# the photos and videos of Debian's opencv-doc package (never ../shared/data). The build runs this
# (apps/dynanav/CMakeLists.txt); run it by hand to retrain:
#   scripts/build_vocabulary.sh build/release/bin/dynanav build/release/share/dynanav/orb_vocabulary.dnvoc
# Extra training folders (e.g. simulator renders) may be given in DYNANAV_VOCABULARY_EXTRA
# (space-separated). Editing the recipe below makes the build retrain.
set -euo pipefail
cli=${1:?usage: build_vocabulary.sh DYNANAV_CLI OUT_FILE}
out=${2:?usage: build_vocabulary.sh DYNANAV_CLI OUT_FILE}
data=${DYNANAV_VOCABULARY_DATA:-/usr/share/doc/opencv-doc/examples/data}
if [ ! -d "$data" ]; then
  echo "warning: $data not found (apt-get install opencv-doc, or run scripts/setup.sh):" \
       "no ORB vocabulary built; relocalisation and loop closing will be unavailable" >&2
  exit 0
fi
mkdir -p "$(dirname "$out")"
# Recipe v1: k = 10, L = 6 (as ORB-SLAM2), 1000 ORB features per image, every 10th video frame, seed 1.
# shellcheck disable=SC2086
"$cli" vocabulary train "$data" ${DYNANAV_VOCABULARY_EXTRA:-} --out "$out.tmp" \
  --k 10 --levels 6 --features 1000 --video-step 10 --seed 1
mv "$out.tmp" "$out"
