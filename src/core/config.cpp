#include "core/config.hpp"

#include <yaml-cpp/yaml.h>

#include <fstream>
#include <set>
#include <sstream>

#include "core/error.hpp"

namespace dynanav {
namespace {

/// Reads the fields a section visits from a YAML map, remembering which keys it knew.
class YamlReader {
 public:
  YamlReader(const YAML::Node& node, std::string where) : node_(node), where_(std::move(where)) {}

  template <class T>
  void operator()(const char* key, T& value, const char* /*doc*/) {
    known_.insert(key);
    const YAML::Node field = node_[key];
    if (!field) return;
    try {
      value = field.as<T>();
    } catch (const YAML::Exception&) {
      throw ConfigError(where_, std::string("key '") + key + "' has a value of the wrong type");
    }
  }

  void rejectUnknownKeys() const {
    for (const auto& kv : node_) {
      const auto key = kv.first.as<std::string>();
      if (!known_.count(key)) throw ConfigError(where_, "unknown key '" + key + "'");
    }
  }

 private:
  YAML::Node node_;
  std::string where_;
  std::set<std::string> known_;
};

/// Writes fields as `key: value  # doc`.
class YamlWriter {
 public:
  explicit YamlWriter(std::ostringstream& out) : out_(out) {}
  template <class T>
  void operator()(const char* key, const T& value, const char* doc) {
    YAML::Emitter e;
    e << YAML::Flow << value;
    out_ << "  " << key << ": " << e.c_str() << "  # " << doc << "\n";
  }

 private:
  std::ostringstream& out_;
};

}  // namespace

Config Config::parse(const std::string& yaml_text, const std::string& source) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::Exception& e) {
    throw ConfigError(source, std::string("not valid YAML: ") + e.what());
  }
  Config config;
  if (!root || root.IsNull()) return config;
  if (!root.IsMap()) throw ConfigError(source, "top level must be a map of sections");
  std::set<std::string> sections;
  config.visitSections([&](const char* name, auto& section) {
    sections.insert(name);
    const YAML::Node node = root[name];
    if (!node) return;
    if (!node.IsMap()) throw ConfigError(source, std::string("section '") + name + "' must be a map");
    YamlReader reader(node, source + " [" + name + "]");
    section.visit(reader);
    reader.rejectUnknownKeys();
  });
  for (const auto& kv : root) {
    const auto key = kv.first.as<std::string>();
    if (!sections.count(key)) throw ConfigError(source, "unknown section '" + key + "'");
  }
  return config;
}

Config Config::load(const std::string& yaml_path) {
  std::ifstream in(yaml_path);
  if (!in) throw ConfigError(yaml_path, "cannot open config file");
  std::stringstream text;
  text << in.rdbuf();
  return parse(text.str(), yaml_path);
}

std::string Config::toYaml() const {
  std::ostringstream out;
  out << "# dynanav effective configuration (defaults overridden by --config and flags)\n";
  auto& self = const_cast<Config&>(*this);  // visit() is shared by readers and writers
  self.visitSections([&](const char* name, auto& section) {
    out << name << ":";
    std::ostringstream fields;
    YamlWriter writer(fields);
    section.visit(writer);
    if (fields.str().empty()) {
      out << " {}\n";
    } else {
      out << "\n" << fields.str();
    }
  });
  return out.str();
}

}  // namespace dynanav
