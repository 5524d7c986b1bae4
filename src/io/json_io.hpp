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
  void write(const nlohmann::json& record);

 private:
  std::ofstream out_;
};

/// Reads a JSON-lines file; throws InputError naming file and line on a malformed line.
std::vector<nlohmann::json> readJsonLines(const std::filesystem::path& path);

void writeJsonFile(const std::filesystem::path& path, const nlohmann::json& value);
/// Throws InputError if missing or malformed.
nlohmann::json readJsonFile(const std::filesystem::path& path);

}  // namespace dynanav
