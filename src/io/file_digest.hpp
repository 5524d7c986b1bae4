#pragma once
// SHA-256 of a file (OpenSSL's libcrypto), to check model files against pinned checksums.
#include <filesystem>
#include <string>

namespace dynanav {

/// Lower-case hex SHA-256 of the file's bytes; InputError naming the file if it cannot be read.
std::string sha256Hex(const std::filesystem::path& path);

}  // namespace dynanav
