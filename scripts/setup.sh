#!/usr/bin/env bash
# Installs every build and run-time dependency of dynanav from Debian's packages.
# Idempotent: runs `apt-get update` only when a package is missing, installs only what is missing.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config ccache
  libopencv-dev libeigen3-dev libceres-dev
  libyaml-cpp-dev libcli11-dev nlohmann-json3-dev libspdlog-dev libfmt-dev libssl-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  clang-format clang-tidy
  clang libclang-rt-14-dev   # the fuzz preset (libFuzzer), scripts/fuzz.sh
  opencv-doc
  liboctomap-dev chromium   # static map (issue 15); report.html's browser test
  libavformat-dev libavcodec-dev libswscale-dev   # annotated.mp4's H.264 (issue 15)
  libespeak-ng-dev espeak-ng-data libopenal-dev libopenal-data libsndfile1-dev   # speech, HRTF audio (issue 14)
  libopenni2-dev            # live OpenNI2 cameras and .oni playback (issue 16); optional in CMake
  python3-numpy python3-opencv openssl   # tools/tfjs_to_pb, its tests, fetch_models.sh's checks
)
# scripts/fetch_models.sh gets the models with npm; a node.js from elsewhere (e.g. NodeSource)
# brings its own npm, so Debian's is installed only when there is none.
command -v npm >/dev/null || packages+=(npm)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "setup: done"
