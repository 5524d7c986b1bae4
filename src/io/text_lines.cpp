#include "io/text_lines.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>

#include "core/error.hpp"

namespace dynanav {

std::vector<TextLine> readContentLines(const std::filesystem::path& path) {
  // A folder, a device (/dev/zero would be read forever) or a symlink loop is not a text file.
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
    throw InputError(path.string(), "not a regular file");
  if (ec && ec != std::errc::no_such_file_or_directory)
    throw InputError(path.string(), "cannot read file: " + ec.message());
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw InputError(path.string(),
                     std::filesystem::exists(path) ? "cannot read file" : "file not found");
  }
  std::vector<TextLine> lines;
  std::string raw;
  int number = 0;
  while (std::getline(in, raw)) {
    ++number;
    const auto first = raw.find_first_not_of(" \t\r");
    if (first == std::string::npos || raw[first] == '#') continue;
    const auto last = raw.find_last_not_of(" \t\r");
    lines.push_back({number, raw.substr(first, last - first + 1)});
  }
  return lines;
}

std::vector<std::string> splitFields(const std::string& line) {
  std::vector<std::string> fields;
  std::string current;
  for (const char c : line) {
    if (c == ' ' || c == '\t' || c == ',') {
      if (!current.empty()) fields.push_back(std::move(current));
      current.clear();
    } else {
      current += c;
    }
  }
  if (!current.empty()) fields.push_back(std::move(current));
  return fields;
}

bool parseFiniteDouble(const std::string& text, double& value) {
  if (text.empty()) return false;
  errno = 0;
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return errno == 0 && end == text.c_str() + text.size() && std::isfinite(value);
}

std::string where(const std::filesystem::path& path, int line) {
  return path.string() + ":" + std::to_string(line);
}

}  // namespace dynanav
