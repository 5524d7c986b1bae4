#pragma once
// One colour per id (instances, tracks), shared by every picture so an id keeps its colour.
#include <cstdint>
#include <opencv2/core.hpp>

namespace dynanav {

/// Well-separated hues from the golden ratio, so neighbouring ids differ (BGR).
cv::Scalar colourOfId(uint64_t id);

}  // namespace dynanav
