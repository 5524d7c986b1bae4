#include "io/json_io.hpp"

#include <sstream>

#include "core/error.hpp"
#include "io/text_lines.hpp"

namespace dynanav {

JsonLinesWriter::JsonLinesWriter(const std::filesystem::path& path) : out_(path) {
  if (!out_) throw InputError(path.string(), "cannot write file");
}

void JsonLinesWriter::write(const nlohmann::json& record) {
  out_ << record.dump() << '\n';
  out_.flush();
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

void writeJsonFile(const std::filesystem::path& path, const nlohmann::json& value) {
  const std::filesystem::path tmp = path.string() + ".tmp";
  {
    std::ofstream out(tmp);
    if (!out) throw InputError(path.string(), "cannot write file");
    out << value.dump(2) << '\n';
  }
  std::filesystem::rename(tmp, path);
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
