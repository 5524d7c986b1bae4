// The vocabulary file: little-endian binary, version 1.
//   magic "DNVOCAB1" | u32 version | u32 k | u32 levels | u32 nodes | u32 words
//   | u64 training images | u64 training descriptors | u64 seed | u32 n + n bytes of source text
//   | per node (breadth-first, root first): u32 parent, 32 bytes centre
//   | per word: f32 idf | u64 FNV-1a hash of every byte before it
// Words are the childless nodes in node order, so they need no ids in the file.
#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "core/error.hpp"
#include "slam/vocabulary/vocabulary.hpp"

namespace dynanav {
namespace {

static_assert(std::endian::native == std::endian::little, "the file format is little-endian");
constexpr char kMagic[8] = {'D', 'N', 'V', 'O', 'C', 'A', 'B', '1'};
constexpr uint32_t kVersion = 1;
constexpr uint32_t kMaxSourceBytes = 1 << 16;
// ORB-SLAM's k = 10, L = 6 tree (1.1 million nodes, 36 bytes each) is 40 MB; four times that is
// more than any tree this format is meant for.
constexpr uint64_t kMaxFileBytes = uint64_t{160} << 20;

uint64_t fnv1a(const char* data, size_t size) {
  uint64_t h = 0xCBF29CE484222325ull;
  for (size_t i = 0; i < size; ++i)
    h = (h ^ static_cast<unsigned char>(data[i])) * 0x100000001B3ull;
  return h;
}

class Writer {
 public:
  template <class T>
  void put(const T& value) {
    putBytes(&value, sizeof(T));
  }
  void putBytes(const void* p, size_t n) { bytes_.append(static_cast<const char*>(p), n); }
  std::string& bytes() { return bytes_; }

 private:
  std::string bytes_;
};

// Reads with bounds checks; every failure names the file.
class Reader {
 public:
  Reader(const std::string& bytes, std::string path) : bytes_(bytes), path_(std::move(path)) {}
  template <class T>
  T get(const char* what) {
    T value;
    getBytes(&value, sizeof(T), what);
    return value;
  }
  void getBytes(void* p, size_t n, const char* what) {
    if (n > bytes_.size() - offset_) fail(std::string("file ends inside ") + what);
    std::memcpy(p, bytes_.data() + offset_, n);
    offset_ += n;
  }
  [[nodiscard]] size_t offset() const { return offset_; }
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(path_, "not a valid dynanav vocabulary: " + what);
  }

 private:
  const std::string& bytes_;
  std::string path_;
  size_t offset_ = 0;
};

}  // namespace

void Vocabulary::save(const std::string& path) const {
  Writer w;
  w.putBytes(kMagic, sizeof(kMagic));
  w.put(kVersion);
  w.put(static_cast<uint32_t>(info_.branching));
  w.put(static_cast<uint32_t>(info_.levels));
  w.put(static_cast<uint32_t>(nodes()));
  w.put(static_cast<uint32_t>(words()));
  w.put(info_.training_images);
  w.put(info_.training_descriptors);
  w.put(info_.seed);
  const std::string source = info_.source.substr(0, kMaxSourceBytes);
  w.put(static_cast<uint32_t>(source.size()));
  w.putBytes(source.data(), source.size());
  for (size_t i = 0; i < nodes(); ++i) {
    w.put(parent_[i]);
    w.putBytes(descriptor_[i].words.data(), 32);
  }
  for (float idf : idf_) w.put(idf);
  w.put(fnv1a(w.bytes().data(), w.bytes().size()));

  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw InputError(path, "cannot write the vocabulary file");
  out.write(w.bytes().data(), static_cast<std::streamsize>(w.bytes().size()));
  if (!out.flush()) throw InputError(path, "writing the vocabulary file failed");
}

Vocabulary Vocabulary::load(const std::string& path) {
  // Only a regular file of bounded size is read: /dev/zero, a FIFO or a terminal would be read
  // forever (or block), a huge file would be read into memory whole.
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status))
    throw InputError(path, "vocabulary file not found" + (ec ? ": " + ec.message() : ""));
  if (!std::filesystem::is_regular_file(status))
    throw InputError(path, "the vocabulary is not a regular file (a device, FIFO or folder)");
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) throw InputError(path, "cannot read the vocabulary file: " + ec.message());
  if (size > kMaxFileBytes)
    throw InputError(path, "vocabulary file of " + std::to_string(size) + " bytes is larger than " +
                               std::to_string(kMaxFileBytes) + " (not a dynanav vocabulary)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open the vocabulary file");
  std::string bytes(size, '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(size));
  if (static_cast<uint64_t>(in.gcount()) != size || in.peek() != std::char_traits<char>::eof())
    throw InputError(path, "the vocabulary file changed size while it was read");
  Reader r(bytes, path);
  char magic[8];
  r.getBytes(magic, sizeof(magic), "the header");
  if (std::memcmp(magic, kMagic, sizeof(kMagic)) != 0) r.fail("wrong magic bytes");
  if (const auto version = r.get<uint32_t>("the header"); version != kVersion)
    r.fail("format version " + std::to_string(version) + ", this build reads " +
           std::to_string(kVersion));
  Vocabulary v;
  v.info_.branching = static_cast<int>(r.get<uint32_t>("the header"));
  v.info_.levels = static_cast<int>(r.get<uint32_t>("the header"));
  const auto n_nodes = r.get<uint32_t>("the header");
  const auto n_words = r.get<uint32_t>("the header");
  v.info_.training_images = r.get<uint64_t>("the header");
  v.info_.training_descriptors = r.get<uint64_t>("the header");
  v.info_.seed = r.get<uint64_t>("the header");
  if (v.info_.branching < 2 || v.info_.branching > 1024) r.fail("branching factor out of range");
  if (v.info_.levels < 1 || v.info_.levels > 16) r.fail("level count out of range");
  const auto source_size = r.get<uint32_t>("the header");
  if (source_size > kMaxSourceBytes) r.fail("source text too long");
  v.info_.source.resize(source_size);
  r.getBytes(v.info_.source.data(), source_size, "the source text");
  // Sizes must add up exactly before anything is allocated from them.
  const uint64_t expected = r.offset() + uint64_t{n_nodes} * 36 + uint64_t{n_words} * 4 + 8;
  if (n_nodes < 2 || n_words < 1 || n_words >= n_nodes || expected != bytes.size())
    r.fail("size " + std::to_string(bytes.size()) + " bytes does not match its header");
  v.parent_.resize(n_nodes);
  v.descriptor_.resize(n_nodes);
  for (uint32_t i = 0; i < n_nodes; ++i) {
    v.parent_[i] = r.get<uint32_t>("the nodes");
    r.getBytes(v.descriptor_[i].words.data(), 32, "the nodes");
  }
  v.idf_.resize(n_words);
  for (auto& idf : v.idf_) {
    idf = r.get<float>("the weights");
    if (!std::isfinite(idf) || idf < 0.0f) r.fail("a word weight is negative or not finite");
  }
  const size_t hashed = r.offset();
  if (r.get<uint64_t>("the checksum") != fnv1a(bytes.data(), hashed))
    r.fail("checksum mismatch (corrupt file)");
  if (const std::string problem = v.index(); !problem.empty()) r.fail(problem);
  if (v.words() != n_words) r.fail("word count does not match the tree");
  return v;
}

}  // namespace dynanav
