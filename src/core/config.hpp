#pragma once
// The Config: all sections, loaded from YAML (unknown keys rejected) and echoed with docs.
#include <string>

#include "core/config/sections.hpp"

namespace dynanav {

struct Config {
  IoConfig io;
  OrbConfig orb;
  TrackingConfig tracking;
  MappingConfig mapping;
  LoopConfig loop;
  PerceptionConfig perception;
  DynamicsConfig dynamics;
  RunConfig run;
  OutputsConfig outputs;

  template <class V> void visitSections(V&& v) {
    v("io", io);
    v("orb", orb);
    v("tracking", tracking);
    v("mapping", mapping);
    v("loop", loop);
    v("perception", perception);
    v("dynamics", dynamics);
    v("run", run);
    v("outputs", outputs);
  }

  /// Config from a YAML file: missing keys keep defaults; unknown keys or wrong types throw
  /// ConfigError naming the file and the key.
  static Config load(const std::string& yaml_path);
  /// Same, from YAML text (`source` names it in errors).
  static Config parse(const std::string& yaml_text, const std::string& source = "<yaml>");
  /// The effective config as YAML, each key with its doc as a comment.
  [[nodiscard]] std::string toYaml() const;
};

}  // namespace dynanav
