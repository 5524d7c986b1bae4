#include <gtest/gtest.h>

#include "core/config.hpp"
#include "core/error.hpp"

using namespace dynanav;

TEST(Config, DefaultsWhenEmpty) {
  const Config c = Config::parse("");
  EXPECT_EQ(c.orb.n_features, 1000);
  EXPECT_DOUBLE_EQ(c.io.max_association_dt_s, 0.02);
}

TEST(Config, OverridesKnownKeys) {
  const Config c = Config::parse("orb:\n  n_features: 1500\nrun:\n  dynamic: false\n");
  EXPECT_EQ(c.orb.n_features, 1500);
  EXPECT_FALSE(c.run.dynamic);
  EXPECT_EQ(c.orb.n_levels, 8);  // untouched keys keep defaults
}

TEST(Config, RejectsUnknownKeyNamingIt) {
  try {
    Config::parse("orb:\n  n_feature: 10\n", "my.yaml");
    FAIL() << "expected ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("n_feature"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("my.yaml"), std::string::npos);
  }
  EXPECT_THROW(Config::parse("nosuchsection:\n  a: 1\n"), ConfigError);
}

TEST(Config, RejectsWrongTypeAndBadYaml) {
  EXPECT_THROW(Config::parse("orb:\n  n_features: many\n"), ConfigError);
  EXPECT_THROW(Config::parse("orb: [1, 2\n"), ConfigError);
  EXPECT_THROW(Config::parse("orb: 3\n"), ConfigError);
}

TEST(Config, EchoRoundTrips) {
  Config c;
  c.orb.n_features = 777;
  c.run.segmenter = "hog";
  const std::string yaml = c.toYaml();
  EXPECT_NE(yaml.find("# ORB features per frame"), std::string::npos);
  const Config back = Config::parse(yaml);
  EXPECT_EQ(back.orb.n_features, 777);
  EXPECT_EQ(back.run.segmenter, "hog");
}

TEST(Config, LoadMissingFileNamesIt) {
  try {
    Config::load("/nonexistent/dir/config.yaml");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/config.yaml"), std::string::npos);
  }
}
