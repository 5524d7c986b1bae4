#pragma once
// Where the vocabulary file is: the project trains it at build time (scripts/build_vocabulary.sh)
// rather than committing a binary, so programs find it next to themselves.
#include <filesystem>
#include <string>

namespace dynanav {

/// Name of the vocabulary the build trains, under <build>/share/dynanav/.
inline constexpr const char* kDefaultVocabularyName = "orb_vocabulary.dnvoc";

/// `configured` if not empty; else $DYNANAV_VOCABULARY if set; else
/// <folder of the running executable>/../share/dynanav/orb_vocabulary.dnvoc. Throws InputError
/// naming the path that was tried when the file does not exist, with how to build it.
std::filesystem::path findVocabulary(const std::string& configured = "");

}  // namespace dynanav
