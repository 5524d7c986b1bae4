#include "io/image_file.hpp"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"

namespace fs = std::filesystem;

namespace dynanav {
namespace {

bool startsWith(const std::vector<unsigned char>& bytes,
                std::initializer_list<unsigned char> head) {
  return bytes.size() >= head.size() && std::equal(head.begin(), head.end(), bytes.begin());
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
      if (bytes[k - 1] == 0xFF && bytes[k] == 0xD9) return {};
    return "truncated JPEG (no end-of-image marker)";
  }
  return {};
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
