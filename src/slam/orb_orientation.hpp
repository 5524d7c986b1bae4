#pragma once
// Keypoint orientation by intensity centroid (Rosin 1999; Rublee et al., ICCV 2011, eqs. 1-3):
// the angle of the vector from the keypoint to the centroid of the intensities in a disc around it,
// theta = atan2(m01, m10) with m_pq = sum x^p y^q I(x, y). A disc (not a square) makes the moments
// rotate with the image.
#include <opencv2/core.hpp>
#include <vector>

namespace dynanav {

/// Half-width of the disc of `radius` at each row offset v = 0..radius: the largest u with
/// u^2 + v^2 <= radius * (radius + 1). The condition is symmetric in u and v, so the disc maps
/// onto itself under 90-degree rotations and reflections.
std::vector<int> orientationDisc(int radius);

/// Orientation in degrees [0, 360) of the keypoint at integer pixel `center` of the 8-bit image
/// (x right, y down, as OpenCV's KeyPoint::angle). `center` must lie at least disc radius pixels
/// inside the image.
float intensityCentroidAngle(const cv::Mat& image, cv::Point center, const std::vector<int>& disc);

}  // namespace dynanav
