#include "io/image_file.hpp"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>

#include "core/error.hpp"

namespace fs = std::filesystem;

namespace dynanav {
namespace {

bool startsWith(const std::vector<unsigned char>& bytes,
                std::initializer_list<unsigned char> head) {
  return bytes.size() >= head.size() && std::equal(head.begin(), head.end(), bytes.begin());
}

/// The JPEG's frame header (SOFn) read by walking its marker segments: "" when it declares a
/// size up to kMaxSidePx a side, else what is wrong. libjpeg allocates by the declared size
/// before it reads any pixel: a 173-byte file asking for 65535 x 65535 made it request 4 GB
/// (found by fuzz_mask_png).
std::string jpegHeaderProblem(const std::vector<unsigned char>& bytes) {
  constexpr int kMaxSidePx = 16384;
  size_t pos = 2;  // after FF D8
  while (pos + 4 <= bytes.size()) {
    if (bytes[pos] != 0xFF) return "malformed JPEG (no marker where one should be)";
    const unsigned char marker = bytes[pos + 1];
    if (marker == 0xFF) {  // fill byte
      ++pos;
      continue;
    }
    const size_t length = (size_t(bytes[pos + 2]) << 8) | bytes[pos + 3];
    const bool sof =
        marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
    if (sof) {
      if (pos + 9 > bytes.size()) return "truncated JPEG frame header";
      const int height = (int(bytes[pos + 5]) << 8) | bytes[pos + 6];
      const int width = (int(bytes[pos + 7]) << 8) | bytes[pos + 8];
      if (width <= 0 || height <= 0 || width > kMaxSidePx || height > kMaxSidePx)
        return "JPEG declares " + std::to_string(width) + "x" + std::to_string(height) +
               " pixels (at most " + std::to_string(kMaxSidePx) + " a side)";
      return {};
    }
    if (marker == 0xDA || marker == 0xD9 || length < 2)
      return "malformed JPEG (no frame header before the image data)";
    pos += 2 + length;
  }
  return "truncated JPEG (no frame header)";
}

}  // namespace

std::string imageBytesProblem(const std::vector<unsigned char>& bytes) {
  if (bytes.empty()) return "zero bytes";
  if (startsWith(bytes, {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'})) {
    // The last chunk: length 0, type IEND, CRC (4 bytes).
    if (bytes.size() < 20 || std::memcmp(bytes.data() + bytes.size() - 8, "IEND", 4) != 0)
      return "truncated PNG (no IEND chunk at the end)";
    return {};
  }
  if (startsWith(bytes, {0xFF, 0xD8})) {
    // Inside entropy-coded data FF is always followed by 00 or a restart marker, so FF D9 near
    // the end is the end-of-image marker; some cameras pad a few bytes after it.
    const size_t from = bytes.size() > 256 ? bytes.size() - 256 : 2;
    for (size_t k = bytes.size() - 1; k > from; --k)
      if (bytes[k - 1] == 0xFF && bytes[k] == 0xD9) return jpegHeaderProblem(bytes);
    return "truncated JPEG (no end-of-image marker)";
  }
  // OpenCV would pick any of its decoders by content (TIFF, JPEG 2000, DICOM through GDCM, ...);
  // a DICOM header in a file named .png makes GDCM abort the process (found by fuzz_mask_png).
  // Sequences and masks are PNG or JPEG, so nothing else reaches a decoder.
  return "not a PNG or JPEG image";
}

cv::Mat readImageFile(const fs::path& path, int flags, const std::string& what) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path.string(), what + " not found");
  if (!fs::is_regular_file(path, ec)) throw InputError(path.string(), what + " is not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "cannot open " + what);
  const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)),
                                         std::istreambuf_iterator<char>());
  if (in.bad()) throw InputError(path.string(), "cannot read " + what);
  if (const std::string problem = imageBytesProblem(bytes); !problem.empty())
    throw InputError(path.string(), what + ": " + problem);
  cv::Mat image;
  try {
    image = cv::imdecode(bytes, flags);
  } catch (const cv::Exception& e) {
    throw InputError(path.string(), "cannot decode " + what + ": " + e.what());
  }
  if (image.empty()) throw InputError(path.string(), "cannot decode " + what);
  return image;
}

std::string colourFrameProblem(const cv::Mat& bgr) {
  cv::Mat grey = bgr;
  if (bgr.channels() == 3) cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  const double n = static_cast<double>(grey.total());
  // Nearly every pixel at the ends of the range: a covered lens or a blinded sensor.
  if (cv::countNonZero(grey > 5) < 0.01 * n) return "all black";
  if (cv::countNonZero(grey < 250) < 0.01 * n) return "saturated (all white)";
  cv::Scalar mean, stddev;
  cv::meanStdDev(grey, mean, stddev);
  if (stddev[0] < 1.0) return "flat (one colour, no texture)";
  return {};
}

}  // namespace dynanav
