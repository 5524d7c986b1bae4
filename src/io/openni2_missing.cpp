// RgbdDevice without OpenNI2: this build was configured without libopenni2 (openni2_device.cpp
// holds the adapter), so a live camera or an .oni file is refused with the reason and the fix.
#ifndef DYNANAV_HAVE_OPENNI2
#include "core/error.hpp"
#include "io/rgbd_device.hpp"

namespace dynanav {

std::unique_ptr<RgbdDevice> openOpenNi2Device(const RgbdDeviceRequest& request) {
  throw InputError(request.is_file ? request.uri : "openni://" + request.uri,
                   "this build has no OpenNI2 support: libopenni2-dev was not found when it was "
                   "configured (install it with scripts/setup.sh, then configure again)");
}

bool haveOpenNi2() {
  return false;
}

}  // namespace dynanav
#endif  // DYNANAV_HAVE_OPENNI2
