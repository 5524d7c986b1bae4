#include <gtest/gtest.h>

#include <vector>

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

TEST(Config, DefaultsAreInsideTheirRanges) {
  EXPECT_NO_THROW(Config{}.validate("defaults"));
}

TEST(Config, RejectsOutOfRangeNamingFileAndKey) {
  const std::vector<std::string> bad = {"orb:\n  n_features: 0\n",
                                        "orb:\n  n_features: 100000000\n",
                                        "orb:\n  scale_factor: 1.0\n",
                                        "orb:\n  scale_factor: .nan\n",
                                        "orb:\n  n_levels: -3\n",
                                        "tracking:\n  depth_max_m: .inf\n",
                                        "tracking:\n  local_nn_ratio: 0\n",
                                        "mapping:\n  ba_linear_solver: cholesky\n",
                                        "run:\n  segment_every: 0\n",
                                        "run:\n  segmenter: magic\n",
                                        "io:\n  max_association_dt_s: -1\n",
                                        "perception:\n  flow_scale: 2\n",
                                        "dynamics:\n  sample_step_px: 0\n",
                                        "loop:\n  loop_min_ransac_inliers: 2\n"};
  for (const auto& yaml : bad) {
    const std::string key =
        yaml.substr(yaml.find("  ") + 2, yaml.find(':', yaml.find("  ")) - yaml.find("  ") - 2);
    try {
      Config::parse(yaml, "bad.yaml");
      ADD_FAILURE() << "accepted: " << yaml;
    } catch (const ConfigError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("bad.yaml"), std::string::npos) << what;
      EXPECT_NE(what.find("'" + key + "'"), std::string::npos) << what;
    }
  }
}

TEST(Config, ValidateCatchesValuesSetAfterLoading) {
  Config c;
  c.run.queue_frames = 0;
  try {
    c.validate("flags");
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("queue_frames"), std::string::npos);
  }
}

TEST(Config, EchoShowsTheRange) {
  const std::string yaml = Config{}.toYaml();
  EXPECT_NE(yaml.find("scale_factor: 1.2  # scale between pyramid levels (valid: (1, 4])"),
            std::string::npos);
  EXPECT_NE(yaml.find("(valid: auto | dnn | hog | masks | none)"), std::string::npos);
}

// A fuzz finding: a map used as a key made yaml-cpp throw past the loader (std::terminate).
TEST(ConfigFuzzFinding, MapAsKeyIsAConfigError) {
  EXPECT_THROW(dynanav::Config::parse("orb:\n ? n_fea: 67\n run:\n", "fuzz.yaml"),
               dynanav::ConfigError);
  EXPECT_THROW(dynanav::Config::parse("? {a: 1}\n: 2\n", "fuzz.yaml"), dynanav::ConfigError);
}
