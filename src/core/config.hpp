#pragma once
// The Config: all sections, loaded from YAML (unknown keys rejected) and echoed with docs.
#include <string>

#include "core/config/range.hpp"
#include "core/config/sections.hpp"

namespace YAML {
class Node;
}

namespace dynanav {

struct Config {
  IoConfig io;
  OrbConfig orb;
  TrackingConfig tracking;
  MappingConfig mapping;
  LoopConfig loop;
  PerceptionConfig perception;
  DynamicsConfig dynamics;
  ObjectTrackingConfig objects;
  AssistConfig assist;
  RunConfig run;
  OutputsConfig outputs;
  AudioConfig audio;

  template <class V>
  void visitSections(V&& v) {
    v("io", io);
    v("orb", orb);
    v("tracking", tracking);
    v("mapping", mapping);
    v("loop", loop);
    v("perception", perception);
    v("dynamics", dynamics);
    v("objects", objects);
    v("assist", assist);
    v("run", run);
    v("outputs", outputs);
    v("audio", audio);
  }

  /// Config from a YAML file: missing keys keep defaults; unknown keys or wrong types throw
  /// ConfigError naming the file and the key.
  static Config load(const std::string& yaml_path);
  /// Same, from YAML text (`source` names it in errors).
  static Config parse(const std::string& yaml_text, const std::string& source = "<yaml>");
  /// parse() after YAML::Load: the sections of a loaded document (YAML errors escape).
  static Config parseSections(const YAML::Node& root, const std::string& source);
  /// Throws ConfigError naming `source` and the key when a value is outside its documented
  /// range (each section's visit() gives it; NaN and infinity are never in range). parse()
  /// checks what it reads; call this again after command-line flags changed values.
  void validate(const std::string& source) const;
  /// The effective config as YAML, each key with its doc as a comment.
  [[nodiscard]] std::string toYaml() const;
};

}  // namespace dynanav
