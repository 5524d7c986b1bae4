#include "io/json_io.hpp"

#include <sstream>

#include "core/error.hpp"
#include "io/text_lines.hpp"

namespace dynanav {

JsonLinesWriter::JsonLinesWriter(const std::filesystem::path& path) : path_(path), out_(path) {
  if (!out_) throw InputError(path.string(), "cannot write file");
}

void JsonLinesWriter::write(const nlohmann::json& record) {
  out_ << record.dump() << '\n';
  out_.flush();
  if (!out_) throw InputError(path_.string(), "writing failed (disk full?)");
}

std::vector<nlohmann::json> readJsonLines(const std::filesystem::path& path) {
  std::vector<nlohmann::json> records;
  for (const auto& line : readContentLines(path)) {
    try {
      records.push_back(nlohmann::json::parse(line.text));
    } catch (const nlohmann::json::exception& e) {
      throw InputError(where(path, line.number), std::string("malformed JSON: ") + e.what());
    }
  }
  return records;
}

void writeTextFile(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw InputError(path.string(), "cannot write file");
  out << text;
  out.close();
  if (!out) throw InputError(path.string(), "writing failed (disk full?)");
}

void writeJsonFile(const std::filesystem::path& path, const nlohmann::json& value) {
  const std::filesystem::path tmp = path.string() + ".tmp";
  std::error_code ec;
  try {
    writeTextFile(tmp, value.dump(2) + "\n");
  } catch (const InputError&) {
    std::filesystem::remove(tmp, ec);
    throw InputError(path.string(), "writing failed (disk full?)");
  }
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw InputError(path.string(), "cannot replace file: " + ec.message());
  }
}

nlohmann::json readJsonFile(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path.string(), "file not found");
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path.string(), std::string("malformed JSON: ") + e.what());
  }
}

}  // namespace dynanav
