# Sourced by the benchmark scripts that take [BUILD_DIR] [OUT_DIR] [N] [SEQ_DIR] [run flags...]
# (realtime_results.sh, lag_results.sh): sets build, out, count, seq, flags (default
# --segmenter dnn) and cli, and checks them. The caller sets default_out and default_count first.
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
build=${1:-build/release}
out=${2:-$default_out}
count=${3:-$default_count}
seq=${4:-../shared/data/rgbd_bonn_crowd}
shift $(($# < 4 ? $# : 4))
flags=("$@")
[[ ${#flags[@]} -gt 0 ]] || flags=(--segmenter dnn)
cli="$build/bin/dynanav"
[[ -x "$cli" ]] || { echo "no $cli: build first (cmake --build --preset release)" >&2; exit 2; }
[[ -d "$seq" ]] || { echo "no sequence $seq" >&2; exit 2; }
mkdir -p "$out"
