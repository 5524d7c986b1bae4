#include "core/config.hpp"

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <type_traits>

#include "core/error.hpp"

namespace dynanav {
namespace {

template <class T>
std::string showValue(const T& value) {
  YAML::Emitter e;
  e << YAML::Flow << value;
  return e.c_str();
}

template <class T, class C>
void checkValue(const std::string& where, const char* key, const T& value, const C& valid) {
  // Every numeric key documents its range: a new key without one does not compile.
  static_assert(!std::is_arithmetic_v<T> || std::is_same_v<T, bool> || std::is_same_v<C, Range>,
                "numeric config keys need a Range (core/config/range.hpp)");
  if (valid.contains(value)) return;
  throw ConfigError(where, std::string("key '") + key + "' = " + showValue(value) +
                               " is out of range, expected " + valid.describe());
}

/// Checks every field against its constraint (after flags changed a loaded config).
class Validator {
 public:
  explicit Validator(std::string where) : where_(std::move(where)) {}
  template <class T, class C = AnyValue>
  void operator()(const char* key, const T& value, const char* /*doc*/, const C& valid = {}) {
    checkValue(where_, key, value, valid);
  }

 private:
  std::string where_;
};

/// Reads the fields a section visits from a YAML map, remembering which keys it knew.
class YamlReader {
 public:
  YamlReader(const YAML::Node& node, std::string where) : node_(node), where_(std::move(where)) {}

  template <class T, class C = AnyValue>
  void operator()(const char* key, T& value, const char* /*doc*/, const C& valid = {}) {
    known_.insert(key);
    const YAML::Node field = node_[key];
    if (!field) return;
    try {
      value = field.as<T>();
    } catch (const YAML::Exception&) {
      throw ConfigError(where_,
                        std::string("key '") + key + "' has a value of the wrong type" +
                            (valid.describe().empty() ? "" : ", expected " + valid.describe()));
    }
    checkValue(where_, key, value, valid);
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
  template <class T, class C = AnyValue>
  void operator()(const char* key, const T& value, const char* doc, const C& valid = {}) {
    out_ << "  " << key << ": " << showValue(value) << "  # " << doc;
    if (const std::string range = valid.describe(); !range.empty())
      out_ << " (valid: " << range << ")";
    out_ << "\n";
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
  try {
    return parseSections(root, source);
  } catch (const YAML::Exception& e) {  // e.g. a map used as a key (a fuzz finding)
    throw ConfigError(source, std::string("malformed YAML structure: ") + e.what());
  }
}

Config Config::parseSections(const YAML::Node& root, const std::string& source) {
  Config config;
  if (!root || root.IsNull()) return config;
  if (!root.IsMap()) throw ConfigError(source, "top level must be a map of sections");
  std::set<std::string> sections;
  config.visitSections([&](const char* name, auto& section) {
    sections.insert(name);
    const YAML::Node node = root[name];
    if (!node) return;
    if (!node.IsMap())
      throw ConfigError(source, std::string("section '") + name + "' must be a map");
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

void Config::validate(const std::string& source) const {
  auto& self = const_cast<Config&>(*this);  // visit() is shared by readers and writers
  self.visitSections([&](const char* name, auto& section) {
    Validator validator(source + " [" + name + "]");
    section.visit(validator);
  });
}

Config Config::load(const std::string& yaml_path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(yaml_path, ec))
    throw ConfigError(yaml_path, ec ? "cannot open config file: " + ec.message()
                                    : std::string("config file not found (or not a file)"));
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
