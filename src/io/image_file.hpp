#pragma once
// Reading image files as a camera pipeline must: a missing, empty, truncated or undecodable file
// is an InputError naming it, never an image with a grey bottom. OpenCV decodes a truncated JPEG
// with only a libjpeg warning on stderr and returns the filled-in image; a truncated PNG may
// decode too. So the bytes are checked first: a PNG must end with its IEND chunk, a JPEG must
// hold its end-of-image marker (FF D9) near the end.
#include <filesystem>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace dynanav {

/// Empty string when `bytes` look complete, else why not ("zero bytes", "truncated PNG: ...").
/// Formats other than PNG and JPEG are left to the decoder.
std::string imageBytesProblem(const std::vector<unsigned char>& bytes);

/// The file decoded with cv::imdecode `flags`; InputError naming `path` (with `what`, e.g.
/// "colour image") when it is missing, unreadable, empty, truncated or cannot be decoded.
cv::Mat readImageFile(const std::filesystem::path& path, int flags, const std::string& what);

/// Empty string when a colour frame has content, else why it is unusable: all black, saturated
/// (white) or flat (one colour; no feature can be found on it).
std::string colourFrameProblem(const cv::Mat& bgr);

}  // namespace dynanav
