#include "control/genome.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "files/errors.h"
#include "tests/temp_dir_test.h"

namespace walkers {
namespace {

std::string DataPath(const std::string& relative) { return std::string(WALKERS_SOURCE_DIR) + "/" + relative; }

class GenomeFileTest : public TempDirTest {
 protected:
  std::string Write(const std::string& name, const std::string& text) {
    const std::string path = (root_ / name).string();
    std::ofstream(path) << text;
    return path;
  }
  // the default genome's JSON with one key changed (or removed when value is null)
  std::string WriteDefaultWith(const std::string& key, const nlohmann::json& value) {
    nlohmann::json json = GenomeToJson(DefaultGenome());
    if (value.is_null()) {
      json.erase(key);
    } else {
      json[key] = value;
    }
    return Write("genome.json", json.dump());
  }
  // the error message of loading path, or "" if it loaded
  static std::string LoadError(const std::string& path) {
    try {
      LoadGenome(path);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
};

TEST_F(GenomeFileTest, DefaultFileHoldsTheInitialIndividual) {
  const Genome g = LoadGenome(DataPath("data/genomes/default.json"));
  const Genome d = DefaultGenome();
  EXPECT_EQ(g.genes, d.genes);
  EXPECT_EQ(g.knee_mass, 0.7);
  EXPECT_EQ(g.ankle_mass, 0.1);
  EXPECT_EQ(g.hip_mass, 0.1);
  EXPECT_DOUBLE_EQ(d[kHalfBodyX], 0.8822120184545844);
  EXPECT_DOUBLE_EQ(d[kStepOffset], -0.00213586038101777);
  EXPECT_DOUBLE_EQ(GeneTable()[kLambdaTheta].sigma, 103.77362891303223 / 11);
}

TEST_F(GenomeFileTest, SavedFilesLoadBackBitForBit) {
  Genome g = DefaultGenome();
  g[kKy] = 12345.678901234567;
  g[kHalfBodyX] = 0.033;
  const std::string path = (root_ / "round.json").string();
  SaveGenome(g, path);
  const Genome back = LoadGenome(path);
  EXPECT_EQ(back.genes, g.genes);
  // keys are exactly the gene names
  std::ifstream in(path);
  const nlohmann::json json = nlohmann::json::parse(in);
  EXPECT_EQ(json.size(), static_cast<size_t>(kNumGenes + 3));
  EXPECT_TRUE(json.contains("lambdaTheta"));
  EXPECT_TRUE(json.contains("hipMass"));
}

TEST_F(GenomeFileTest, RejectsAMissingGene) {
  const std::string error = LoadError(WriteDefaultWith("kStep", nullptr));
  EXPECT_NE(error.find("missing gene 'kStep'"), std::string::npos) << error;
  EXPECT_NE(error.find("genome.json"), std::string::npos) << error;
}

TEST_F(GenomeFileTest, RejectsAnUnknownGene) {
  const std::string error = LoadError(WriteDefaultWith("kneeStiffness", 3.0));
  EXPECT_NE(error.find("unknown gene 'kneeStiffness'"), std::string::npos) << error;
}

TEST_F(GenomeFileTest, RejectsANonNumber) {
  const std::string error = LoadError(WriteDefaultWith("ky", "stiff"));
  EXPECT_NE(error.find("'ky' must be a number"), std::string::npos) << error;
}

TEST_F(GenomeFileTest, RejectsInfinity) {
  nlohmann::json json = GenomeToJson(DefaultGenome());
  std::string text = json.dump();
  const std::string key = "\"kx\":";
  const size_t at = text.find(key) + key.size();
  text.replace(at, text.find(',', at) - at, "1e999");  // parses to infinity
  const std::string error = LoadError(Write("inf.json", text));
  EXPECT_NE(error.find("'kx'"), std::string::npos) << error;
}

TEST_F(GenomeFileTest, RejectsAValueOutsideItsRangeAndNamesTheRange) {
  const std::string error = LoadError(WriteDefaultWith("femurLength", 2.5));
  EXPECT_NE(error.find("'femurLength' = 2.5"), std::string::npos) << error;
  // bounds print as the shortest text that reads back exactly
  EXPECT_NE(error.find("[0.1, 1.9]"), std::string::npos) << error;
  EXPECT_NE(LoadError(WriteDefaultWith("ky", 2999.0)), "");
  EXPECT_NE(LoadError(WriteDefaultWith("hipMass", -1.0)), "");
}

TEST_F(GenomeFileTest, AcceptsTheAuthorsShortTrunksButNotAVanishingOne) {
  EXPECT_EQ(LoadError(WriteDefaultWith("halfBodyX", 0.033)), "");
  const std::string error = LoadError(WriteDefaultWith("halfBodyX", 0.005));
  EXPECT_NE(error.find("'halfBodyX'"), std::string::npos) << error;
}

TEST_F(GenomeFileTest, RejectsADuplicatedGeneNamingIt) {
  // the last value would win and hide the out-of-range first one
  std::string text = GenomeToJson(DefaultGenome()).dump();
  text.insert(1, "\"kStep\": 900, ");
  const std::string error = LoadError(Write("twice.json", text));
  EXPECT_NE(error.find("twice.json: key 'kStep' appears twice"), std::string::npos) << error;
}

TEST_F(GenomeFileTest, RejectsDeepNestingWithoutCrashing) {
  const std::string text = "{\"kx\": " + std::string(100000, '[') + std::string(100000, ']') + "}";
  const std::string error = LoadError(Write("deep.json", text));
  EXPECT_NE(error.find("nested more than"), std::string::npos) << error;
}

TEST_F(GenomeFileTest, RejectsFilesThatAreNotGenomes) {
  EXPECT_NE(LoadError(Write("broken.json", "{\"kx\": ")).find("not valid JSON"), std::string::npos);
  EXPECT_NE(LoadError(Write("array.json", "[1, 2]")).find("JSON object"), std::string::npos);
  EXPECT_NE(LoadError((root_ / "absent.json").string()).find("cannot open"), std::string::npos);
}

// every genome the repository keeps (benchmark, authors', sampled) is a valid genome file
TEST(GenomeTest, EveryStoredGenomeLoads) {
  int files = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(DataPath("data/genomes"))) {
    if (entry.path().extension() != ".json") continue;
    ++files;
    EXPECT_NO_THROW(LoadGenome(entry.path().string())) << entry.path();
  }
  EXPECT_GE(files, 9 + 36 + 66);
}

}  // namespace
}  // namespace walkers
