// Test fixture: records an .oni file from OpenNI2's own DummyDevice driver (URI "Dummy": a
// 320x240 colour and depth pair at 30 frames/s, a small ball on black), so the OpenNI2 adapter's
// playback path runs in tests on a machine without a camera. Usage: oni_record_dummy OUT.oni N
// Exit 0 with OUT.oni holding at least N depth frames; 1 with a message otherwise.
#include <OpenNI.h>

#include <cstdio>
#include <cstdlib>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: oni_record_dummy OUT.oni FRAMES\n");
    return 1;
  }
  const int frames = std::atoi(argv[2]);
  using namespace openni;
  Device device;
  VideoStream depth, colour;
  Recorder recorder;
  if (OpenNI::initialize() != STATUS_OK || device.open("Dummy") != STATUS_OK ||
      depth.create(device, SENSOR_DEPTH) != STATUS_OK ||
      colour.create(device, SENSOR_COLOR) != STATUS_OK || recorder.create(argv[1]) != STATUS_OK ||
      recorder.attach(depth) != STATUS_OK || recorder.attach(colour) != STATUS_OK ||
      depth.start() != STATUS_OK || colour.start() != STATUS_OK || recorder.start() != STATUS_OK) {
    std::fprintf(stderr, "oni_record_dummy: %s\n", OpenNI::getExtendedError());
    return 1;
  }
  // The recorder writes frames as the driver delivers them; a few extra reads make sure the
  // last of the N has reached the file before it is closed.
  for (int i = 0; i < frames + 3; ++i) {
    VideoFrameRef frame;
    if (depth.readFrame(&frame) != STATUS_OK || colour.readFrame(&frame) != STATUS_OK) {
      std::fprintf(stderr, "oni_record_dummy: %s\n", OpenNI::getExtendedError());
      return 1;
    }
  }
  recorder.stop();
  recorder.destroy();
  depth.stop();
  colour.stop();
  depth.destroy();
  colour.destroy();
  device.close();
  // No OpenNI::shutdown(): it unloads the DummyDevice driver while the driver's frame thread
  // still runs, which crashes (OpenNI2 2.2). The process ends here anyway.
  return 0;
}
