#pragma once
// JSON outputs: JSON-lines streams (objects.jsonl, events.jsonl) flushed per line, and whole
// JSON files (stats.json) written atomically (temp file + rename) so readers never see half.
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

namespace dynanav {

class JsonLinesWriter {
 public:
  explicit JsonLinesWriter(const std::filesystem::path& path);
  /// Throws InputError naming the file when the line cannot be written (disk full).
  void write(const nlohmann::json& record);

 private:
  std::filesystem::path path_;
  std::ofstream out_;
};

/// Reads a JSON-lines file; throws InputError naming file and line on a malformed line.
std::vector<nlohmann::json> readJsonLines(const std::filesystem::path& path);

/// Atomic: temp file, checked write and close, rename; InputError naming the file on failure
/// (the temp file is removed, an earlier file at `path` is left as it was).
void writeJsonFile(const std::filesystem::path& path, const nlohmann::json& value);
/// Writes `text` to `path` (replacing it), checking every byte reached the file.
void writeTextFile(const std::filesystem::path& path, const std::string& text);
/// Throws InputError if missing or malformed.
nlohmann::json readJsonFile(const std::filesystem::path& path);

}  // namespace dynanav
