#pragma once
// Line-oriented parsing shared by the TUM list, trajectory and JSON-lines readers: strips CR,
// skips blank and '#' lines, and remembers 1-based line numbers for error messages.
#include <filesystem>
#include <string>
#include <vector>

namespace dynanav {

struct TextLine {
  int number = 0;    ///< 1-based
  std::string text;  ///< without CR/LF, trimmed
};

/// Content lines of a text file. Throws InputError if the file cannot be opened.
std::vector<TextLine> readContentLines(const std::filesystem::path& path);

/// Whitespace/comma separated fields of a line.
std::vector<std::string> splitFields(const std::string& line);

/// Parses a finite double; false on garbage, trailing characters, NaN or infinity.
bool parseFiniteDouble(const std::string& text, double& value);

/// "path:line" for messages.
std::string where(const std::filesystem::path& path, int line);

}  // namespace dynanav
