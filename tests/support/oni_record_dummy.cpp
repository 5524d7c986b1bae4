// Test fixture: records an .oni file from OpenNI2's own DummyDevice driver (URI "Dummy": a
// 320x240 colour and depth pair at 30 frames/s, a small ball on black), so the OpenNI2 adapter's
// playback path runs in tests on a machine without a camera. Usage:
//   oni_record_dummy OUT.oni N [--as-recorded]
// Exit 0 with OUT.oni holding at least N frames of each stream (the counts are printed); 1 with a
// message otherwise.
//
// Two things make the DummyDevice's recording unlike a camera's, and the fixture mends them in
// place (same record sizes, so every offset and the seek tables stay valid) unless --as-recorded:
// - It reports no cropping, so the recording has no xnCropping property; OpenNI2 2.2's player
//   (PlayerStream::OnNewDataCallback) then drops every frame. A PrimeSense device's recording
//   has one. The fixture turns the player-unused xnSupportedMapOutputModes record of each
//   stream into an xnCropping record (cropping off), zero-padded to the same size.
// - Its colour is a ball on black, which the frame source rightly skips as "all black". The
//   fixture writes a textured image, different per frame, over each (uncompressed) colour frame.
#include <OpenNI.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <thread>
#include <vector>

namespace {

// ONI file layout (OpenNI 1.x format, written by OpenNI2 2.2's FileRecorder): a 24-byte header,
// then records of a 28-byte header (magic "NIR\0", type, node id, size of header + fields,
// payload size, undo position) with fields, then the payload.
constexpr size_t kFileHeaderBytes = 24, kRecordHeaderBytes = 28;
constexpr uint32_t kNodeAdded = 13, kGeneralProperty = 6, kNewData = 10, kEnd = 11;
constexpr uint32_t kImageNode = 3;           // XN_NODE_TYPE_IMAGE
constexpr uint32_t kNewDataFieldBytes = 12;  // timestamp (8), frame number (4)

uint32_t u32(const std::vector<uint8_t>& b, size_t at) {
  uint32_t v;
  std::memcpy(&v, &b[at], 4);
  return v;
}
void put32(std::vector<uint8_t>& b, size_t at, uint32_t v) {
  std::memcpy(&b[at], &v, 4);
}
std::string name(const std::vector<uint8_t>& b, size_t at) {  // length-prefixed, NUL included
  const uint32_t length = u32(b, at);
  return length ? std::string(reinterpret_cast<const char*>(&b[at + 4]), length - 1) : "";
}

/// An xnCropping record's fields (cropping off), padded with zeros to `bytes`.
bool writeCroppingFields(std::vector<uint8_t>& b, size_t at, size_t bytes) {
  const char prop[] = "xnCropping";
  const size_t needed = 4 + sizeof(prop) + 4 + 12;  // name, data size, XnCropping (12 bytes)
  if (bytes < needed) return false;
  std::memset(&b[at], 0, bytes);
  put32(b, at, sizeof(prop));
  std::memcpy(&b[at + 4], prop, sizeof(prop));
  put32(b, at + 4 + sizeof(prop), 12);
  return true;
}

/// A texture that changes from frame to frame: neither black, white nor flat.
void writeTexture(uint8_t* rgb, uint32_t bytes, uint32_t frame) {
  for (uint32_t i = 0; i + 2 < bytes; i += 3) {
    const uint32_t pixel = i / 3, x = pixel % 320, y = pixel / 320;
    const uint32_t cell = ((x + 3 * frame) / 8) * 2654435761u ^ (y / 8) * 40503u;
    const auto v = static_cast<uint8_t>(40 + (cell >> 7) % 170);
    rgb[i] = v;
    rgb[i + 1] = static_cast<uint8_t>(255 - v);
    rgb[i + 2] = static_cast<uint8_t>(v / 2 + 60);
  }
}

/// Mends the recording as described at the top; returns frames per node id, empty on a
/// layout it does not know.
std::map<uint32_t, int> mend(const char* path, bool mend_content) {
  std::ifstream in(path, std::ios::binary);
  std::vector<uint8_t> b((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::map<uint32_t, int> frames;
  std::map<uint32_t, uint32_t> node_type;
  size_t at = kFileHeaderBytes;
  while (at + kRecordHeaderBytes <= b.size()) {
    if (std::memcmp(&b[at], "NIR", 4) != 0) return {};
    const uint32_t type = u32(b, at + 4), node = u32(b, at + 8);
    const size_t fields = u32(b, at + 12), payload = u32(b, at + 16);
    if (fields < kRecordHeaderBytes || at + fields + payload > b.size()) return {};
    const size_t f = at + kRecordHeaderBytes;
    if (type == kNodeAdded) node_type[node] = u32(b, f + 4 + u32(b, f));  // after the name
    if (mend_content && type == kGeneralProperty && name(b, f) == "xnSupportedMapOutputModes" &&
        !writeCroppingFields(b, f, fields - kRecordHeaderBytes))
      return {};
    if (type == kNewData) {
      const uint32_t frame = u32(b, f + 8);
      ++frames[node];
      if (mend_content && node_type[node] == kImageNode && payload == 320u * 240u * 3u &&
          fields == kRecordHeaderBytes + kNewDataFieldBytes)
        writeTexture(&b[at + fields], uint32_t(payload), frame);
    }
    if (type == kEnd) break;
    at += fields + payload;
  }
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(b.data()), std::streamsize(b.size()));
  if (!out) return {};
  return frames;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3 || argc > 4 || (argc == 4 && std::string(argv[3]) != "--as-recorded")) {
    std::fprintf(stderr, "usage: oni_record_dummy OUT.oni FRAMES [--as-recorded]\n");
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
  // The streams stop before the recorder goes. OpenNI2 2.2 takes its locks in opposite orders
  // when a frame arrives (the stream's recorder list, then the recorder's stream list) and when
  // a recorder is destroyed (its stream list, then each stream's recorder list): a frame
  // arriving during Recorder::destroy() deadlocked 11 of 120 recordings here (4 at once on the
  // loaded 2-core machine); with the streams stopped first, 0 of 120.
  // The DummyDevice's frame threads only see a flag at stop and finish their 33 ms sleep first.
  depth.stop();
  colour.stop();
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  recorder.stop();
  recorder.destroy();
  depth.destroy();
  colour.destroy();
  device.close();
  // No OpenNI::shutdown(): it unloads the DummyDevice driver while the driver's frame thread
  // still runs, which crashes (OpenNI2 2.2). The process ends here anyway.
  const bool as_recorded = argc == 4;
  const std::map<uint32_t, int> counts = mend(argv[1], !as_recorded);
  if (counts.size() != 2) {
    std::fprintf(stderr, "oni_record_dummy: %s: not the two-stream layout expected\n", argv[1]);
    return 1;
  }
  for (const auto& [node, n] : counts) {
    std::printf("node %u: %d frames\n", node, n);
    if (n < frames) {
      std::fprintf(stderr, "oni_record_dummy: node %u has %d frames, fewer than %d\n", node, n,
                   frames);
      return 1;
    }
  }
  return 0;
}
