#include "evolve/reproduction.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "files/csv.h"
#include "files/input_file.h"
#include "files/results_folder.h"
#include "tests/evolve/individuals.h"
#include "tests/temp_dir_test.h"

namespace walkers {
namespace {
namespace fs = std::filesystem;
using testing::Threads;

// nine tiny runs: one generation of two children, half a second each
ReproductionConfig Tiny(std::uint64_t seed = 5) {
  ReproductionConfig c;
  c.generations = 1;
  c.replicates = 1;
  c.seed = seed;
  c.ga.population = 2;
  c.ga.archive_size = 2;
  c.ga.mutation_children = 1;
  c.evaluation.duration = 0.5;
  c.ensemble = 3;
  return c;
}

class ReproductionTest : public TempDirTest {
 protected:
  static std::string Error(const std::function<void()>& f) {
    try {
      f();
    } catch (const std::exception& e) {
      return e.what();
    }
    return "";
  }
  // resumes the reproduction in `dir` as `config`; how many batches of finals it re-scored
  static int ResumeCountingRescores(const ReproductionConfig& config, const std::string& dir) {
    int rescored = 0;
    ReproductionObserver observer;
    observer.on_rescore = [&](int, int) { ++rescored; };
    Reproduction(config, dir, StartMode::kResume).Run(Threads(2), observer);
    return rescored;
  }
};

TEST_F(ReproductionTest, RefusesToReplaceOrToShareAReproduction) {
  Reproduction(Tiny(), Dir("r"), StartMode::kNew).Run(Threads(2));
  const std::string manifest = ReadFile(ReproductionFiles(Dir("r")).manifest);
  EXPECT_NE(Error([&] { Reproduction(Tiny(), Dir("r"), StartMode::kNew); }).find("holds a reproduction already"),
            std::string::npos);
  {
    Reproduction first(Tiny(), Dir("r"), StartMode::kResume);
    const std::string error = Error([&] { Reproduction(Tiny(), Dir("r"), StartMode::kResume); });
    EXPECT_NE(error.find("another walkers process (pid " + std::to_string(::getpid()) + ") is writing this reproduction"),
              std::string::npos)
        << error;
  }
  EXPECT_EQ(ReadFile(ReproductionFiles(Dir("r")).manifest), manifest);
  EXPECT_NE(Error([&] { Reproduction(Tiny(), Dir("absent"), StartMode::kResume); }).find("no reproduction to resume"),
            std::string::npos);
  EXPECT_FALSE(fs::exists(Dir("absent")));
}

TEST_F(ReproductionTest, ForceKeepsTheOldReproductionUntilTheFirstNewCheckpoint) {
  Reproduction(Tiny(), Dir("r"), StartMode::kNew).Run(Threads(2));
  const std::string manifest = ReadFile(ReproductionFiles(Dir("r")).manifest);
  const std::string evaluations = ReadFile(Dir("r") + "/time-1/evaluations.csv");
  std::ofstream(Dir("r") + "/notes.txt") << "mine";
  {
    Reproduction forced(Tiny(6), Dir("r"), StartMode::kForce);
    EXPECT_FALSE(fs::exists(ReproductionFiles(Dir("r")).manifest));
    EXPECT_EQ(ReadFile(Dir("r") + "/replaced/time-1/evaluations.csv"), evaluations);
  }
  // abandoned before it began: the old reproduction is back
  EXPECT_EQ(ReadFile(ReproductionFiles(Dir("r")).manifest), manifest);
  EXPECT_EQ(ReadFile(Dir("r") + "/time-1/evaluations.csv"), evaluations);
  EXPECT_FALSE(fs::exists(Dir("r") + "/replaced"));

  Reproduction(Tiny(6), Dir("r"), StartMode::kForce).Run(Threads(2));
  EXPECT_FALSE(fs::exists(Dir("r") + "/replaced"));
  EXPECT_NE(ReadFile(ReproductionFiles(Dir("r")).manifest), manifest);
  EXPECT_EQ(ReadFile(Dir("r") + "/notes.txt"), "mine");  // not the reproduction's
}

TEST_F(ReproductionTest, ValidatesEveryRunsConfigurationFirst) {
  ReproductionConfig c = Tiny(kMaxSeed);
  c.replicates = 2;  // replicate 2 would have seed kMaxSeed + 1
  EXPECT_EQ(Error([&] { Reproduction(c, Dir("r"), StartMode::kNew); }),
            "seed = 4294967295 is outside its allowed range [0, 4294967294] for 2 replicates (replicate r uses seed + r "
            "- 1)");
  c = Tiny();
  c.ga.population = 1;
  EXPECT_EQ(Error([&] { Reproduction(c, Dir("r"), StartMode::kNew); }),
            "population = 1 is outside its allowed range [2, 100000]");
  EXPECT_FALSE(fs::exists(Dir("r")));
}

// the statistics' input: each run's final best and its best biped and best
// tripod over all its evaluations (those that did not fall), null for none,
// each with the recorded fitness and its re-score
TEST_F(ReproductionTest, ReproductionJsonListsEachRunsFinalsAndTheirRescores) {
  ReproductionConfig c = Tiny();
  c.generations = 2;
  c.evaluation.duration = 2.0;
  Reproduction(c, Dir("r"), StartMode::kNew).Run(Threads(2));
  const nlohmann::json manifest = nlohmann::json::parse(ReadFile(ReproductionFiles(Dir("r")).manifest));
  EXPECT_EQ(manifest.at("ensemble"), 3);
  EXPECT_EQ(manifest.at("population"), 2);
  EXPECT_EQ(manifest.at("scaffolds").size(), Scaffolds().size());
  EXPECT_EQ(manifest.at("scaffolds")[1].at("paper_tripod_finals"), Scaffolds()[1].paper_tripod_finals);
  ASSERT_EQ(manifest["runs"].size(), 3u);
  int found = 0;
  for (const nlohmann::json& run : manifest["runs"]) {
    const nlohmann::json archive = nlohmann::json::parse(ReadFile(Dir("r") + "/" + run["dir"].get<std::string>() +
                                                                  "/archive.json"));
    EXPECT_EQ(run["final_best"]["id"], archive["archive"][0]["id"]);
    EXPECT_EQ(run["final_best"]["fitness"], archive["archive"][0]["fitness"]);
    const std::string path = Dir("r") + "/" + run["dir"].get<std::string>() + "/evaluations.csv";
    CsvReader rows(ReadFile(path), path);
    const int fitness = rows.Column("fitness"), fell = rows.Column("fell"), gait = rows.Column("gait");
    std::optional<double> best_biped, best_tripod;
    while (rows.Next()) {
      if (rows.fields()[fell] == "1") continue;
      std::optional<double>& best = rows.fields()[gait] == "tripod" ? best_tripod : best_biped;
      best = std::max(best.value_or(-1e300), rows.Number(fitness));
    }
    for (const auto& [key, best] : {std::pair{"best_biped", best_biped}, std::pair{"best_tripod", best_tripod}}) {
      ASSERT_TRUE(run.contains(key)) << key;
      if (best) {
        ++found;
        EXPECT_EQ(run[key]["fitness"].get<double>(), *best) << run["dir"] << " " << key;
      } else {
        EXPECT_TRUE(run[key].is_null()) << run["dir"] << " " << key;
      }
    }
    // the same build scores the unperturbed member as the run did
    for (const char* key : {"final_best", "best_biped", "best_tripod"}) {
      if (run[key].is_null()) continue;
      const nlohmann::json& rescore = run[key]["rescore"];
      EXPECT_EQ(rescore["fitness"].size(), 3u) << key;
      EXPECT_EQ(rescore["fitness"][1], run[key]["fitness"]) << run["dir"] << " " << key;
      EXPECT_EQ(rescore["recorded_reproduced"], true) << run["dir"] << " " << key;
    }
  }
  EXPECT_GT(found, 0);  // not all null
  // the walks are the first learner's best biped and best tripod by their re-scores
  const nlohmann::json walks = nlohmann::json::parse(ReadFile(ReproductionFiles(Dir("r")).walks));
  for (const char* gait : {"biped", "tripod"}) {
    const nlohmann::json& pick = manifest["best_" + std::string(gait)];
    if (pick.is_null()) continue;
    EXPECT_EQ(walks[gait]["run"], pick["run"]);
    EXPECT_EQ(walks[gait]["id"], pick["id"]);
    double best = -1e300;
    for (const nlohmann::json& run : manifest["runs"]) {
      const nlohmann::json& f = run["best_" + std::string(gait)];
      if (!f.is_null()) best = std::max(best, f["rescore"]["median"].get<double>());
    }
    for (const nlohmann::json& run : manifest["runs"]) {
      if (run["dir"] != pick["run"]) continue;
      EXPECT_EQ(run["best_" + std::string(gait)]["rescore"]["median"], best) << gait;
    }
  }
}

// a finished reproduction resumed evaluates its finals no more
TEST_F(ReproductionTest, AResumedReproductionTakesItsRescoresFromTheCache) {
  Reproduction(Tiny(), Dir("r"), StartMode::kNew).Run(Threads(2));
  const std::string manifest = ReadFile(ReproductionFiles(Dir("r")).manifest);
  EXPECT_EQ(ResumeCountingRescores(Tiny(), Dir("r")), 0);
  EXPECT_EQ(ReadFile(ReproductionFiles(Dir("r")).manifest), manifest);
  // another ensemble size: the finals again
  ReproductionConfig five = Tiny();
  five.ensemble = 5;
  EXPECT_GT(ResumeCountingRescores(five, Dir("r")), 0);
  const nlohmann::json again = nlohmann::json::parse(ReadFile(ReproductionFiles(Dir("r")).manifest));
  EXPECT_EQ(again["runs"][0]["final_best"]["rescore"]["fitness"].size(), 5u);
}

TEST_F(ReproductionTest, EveryLearnerRunsUnderEveryScaffoldAndIsComparedWithTheOthers) {
  ReproductionConfig c = Tiny();
  c.learners = {"ga", "pso"};
  c.generations = 2;
  std::vector<std::string> names;
  for (const PlannedRun& run : PlanRuns(c)) names.push_back(run.name + ":" + run.config.learner);
  EXPECT_EQ(names, (std::vector<std::string>{"free-1:ga", "time-1:ga", "performance-1:ga", "pso-free-1:pso",
                                             "pso-time-1:pso", "pso-performance-1:pso"}));
  c.replicates = 2;
  const std::vector<PlannedRun> plan = PlanRuns(c);
  std::vector<std::string> started;
  for (std::size_t i : StartOrder(plan)) started.push_back(plan[i].name);
  EXPECT_EQ(started, (std::vector<std::string>{"free-1", "time-1", "performance-1", "pso-free-1", "pso-time-1",
                                               "pso-performance-1", "free-2", "time-2", "performance-2",
                                               "pso-free-2", "pso-time-2", "pso-performance-2"}))
      << "every replicate 1 before any replicate 2";
  c.replicates = 1;
  Reproduction(c, Dir("r"), StartMode::kNew).Run(Threads(2));
  const nlohmann::json manifest = nlohmann::json::parse(ReadFile(ReproductionFiles(Dir("r")).manifest));
  EXPECT_EQ(manifest.at("learners").size(), 2u);
  EXPECT_EQ(manifest.at("learners")[1].at("name"), "pso");
  ASSERT_EQ(manifest.at("runs").size(), 6u) << "every learner's runs";
  for (const nlohmann::json& run : manifest.at("runs")) {
    const nlohmann::json archive = nlohmann::json::parse(ReadFile(Dir("r") + "/" + run.at("dir").get<std::string>() +
                                                                  "/archive.json"));
    EXPECT_EQ(run.at("learner"), archive.value("learner", "ga")) << run.at("dir");
    EXPECT_EQ(run.at("final_best").at("fitness"), archive.at("archive")[0].at("fitness")) << run.at("dir");
  }
  // the walks and the gallery: the first learner's runs only
  const nlohmann::json gallery = nlohmann::json::parse(ReadFile(ReproductionFiles(Dir("r")).gallery));
  for (const nlohmann::json& g : gallery.at("individuals")) EXPECT_EQ(g.at("run").get<std::string>().rfind("pso", 0), std::string::npos);
  // another learner's run folder is a reproduction's too
  fs::remove_all(Dir("r2"));
  fs::create_directories(Dir("r2") + "/cmaes-time-3");
  EXPECT_NE(Error([&] { Reproduction(Tiny(), Dir("r2"), StartMode::kNew); }).find("holds a reproduction already"),
            std::string::npos);
  c.learners = {"pso", "pso"};
  EXPECT_EQ(Error([&] { c.Validate(); }), "learners: 'pso' is given twice");
  c.learners = {};
  EXPECT_EQ(Error([&] { c.Validate(); }), "learners: at least one learner is needed");
  c.learners = {"sade"};  // sade needs 7 children
  EXPECT_EQ(Error([&] { c.Validate(); }), "population = 2 is outside its allowed range [7, 100000] for the learner sade");
}

// every file of a run folder but checkpoint.json (it records byte offsets,
// which the wall-clock columns shift), with the last column of the CSV files
// (wall_ms, evals_per_s) removed
std::map<std::string, std::string> RunFilesWithoutTiming(const std::string& dir) {
  std::map<std::string, std::string> files;
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(dir)) {
    const std::string name = fs::relative(entry.path(), dir).string();
    if (!entry.is_regular_file() || entry.path().filename() == "checkpoint.json" ||
        entry.path().filename() == kLockFileName) {
      continue;
    }
    std::string text = ReadFile(entry.path().string());
    if (entry.path().extension() == ".csv") {
      std::istringstream in(text);
      text.clear();
      for (std::string line; std::getline(in, line);) text += line.substr(0, line.rfind(',')) + "\n";
    }
    files[name] = text;
  }
  return files;
}

TEST_F(ReproductionTest, RunsSideBySideWriteTheSameFilesAsOneAtATime) {
  ReproductionConfig c = Tiny();
  c.generations = 3;
  c.replicates = 2;
  Reproduction(c, Dir("one"), StartMode::kNew).Run(Threads(1), {}, 1);
  // every run at once, their children on two threads
  int generations_reported = 0;
  ReproductionObserver observer;
  observer.on_generation = [&](const PlannedRun&, const GenerationSummary&) { ++generations_reported; };
  Reproduction(c, Dir("side"), StartMode::kNew).Run(Threads(2), observer, 6);
  EXPECT_EQ(generations_reported, 6 * 3);
  const auto one = RunFilesWithoutTiming(Dir("one")), side = RunFilesWithoutTiming(Dir("side"));
  EXPECT_EQ(one.size(), side.size());
  for (const auto& [name, text] : one) {
    ASSERT_TRUE(side.count(name)) << name;
    EXPECT_EQ(text, side.at(name)) << name;
  }
  EXPECT_GE(one.size(), 6u * 5 + 3);
}

TEST_F(ReproductionTest, GrowsByResumingWithMoreReplicates) {
  ReproductionConfig c = Tiny();
  Reproduction(c, Dir("r"), StartMode::kNew).Run(Threads(2), {}, 2);
  const auto first = RunFilesWithoutTiming(Dir("r") + "/time-1");
  c.replicates = 2;
  std::vector<std::string> started;
  ReproductionObserver observer;
  observer.on_run_start = [&](const PlannedRun& run, int completed) {
    if (completed == 0) started.push_back(run.name);
  };
  Reproduction(c, Dir("r"), StartMode::kResume).Run(Threads(2), observer, 3);
  std::sort(started.begin(), started.end());
  EXPECT_EQ(started, (std::vector<std::string>{"free-2", "performance-2", "time-2"}));
  EXPECT_EQ(RunFilesWithoutTiming(Dir("r") + "/time-1"), first);
  const auto manifest = nlohmann::json::parse(ReadFile(ReproductionFiles(Dir("r")).manifest));
  EXPECT_EQ(manifest.at("runs").size(), 6u);
}

// Committed results leave each run's evaluations.csv out: the statistics are
// made again from what is kept (finals.json, the re-score cache).
TEST_F(ReproductionTest, AResumeWithoutTheRunsEvaluationsRemakesTheSameStatistics) {
  Reproduction(Tiny(), Dir("r"), StartMode::kNew).Run(Threads(2));
  const std::string manifest = ReadFile(ReproductionFiles(Dir("r")).manifest);
  for (const PlannedRun& run : PlanRuns(Tiny())) {
    const RunFiles files(Dir("r") + "/" + run.name);
    ASSERT_TRUE(fs::exists(files.finals)) << files.finals;
    fs::remove(files.evaluations);
  }
  EXPECT_EQ(ResumeCountingRescores(Tiny(), Dir("r")), 0);
  EXPECT_EQ(ReadFile(ReproductionFiles(Dir("r")).manifest), manifest);

  // such a run cannot be continued, and a damaged finals.json is named
  ReproductionConfig longer = Tiny();
  longer.generations = 2;
  EXPECT_NE(Error([&] { Reproduction(longer, Dir("r"), StartMode::kResume).Run(Threads(2)); })
                .find("no evaluations.csv: it cannot be continued without them"),
            std::string::npos);
  const std::string finals = RunFiles(Dir("r") + "/free-1").finals;
  nlohmann::json damaged = nlohmann::json::parse(ReadFile(finals));
  damaged["best_biped"] = {{"id", "0/0"}};
  std::ofstream(finals) << damaged.dump();
  const std::string error = Error([&] { Reproduction(Tiny(), Dir("r"), StartMode::kResume).Run(Threads(2)); });
  EXPECT_NE(error.find(finals + ": "), std::string::npos) << error;
  EXPECT_NE(error.find("best_biped."), std::string::npos) << error;
}

// A run's finals.json is written as the run finishes, so that it can be
// committed while the later runs go on; the end does not change it.
TEST_F(ReproductionTest, EachRunWritesItsFinalsAsItFinishes) {
  std::vector<std::string> finished;  // the runs before the one starting
  std::map<std::string, std::string> finals_then;
  ReproductionObserver observer;
  observer.on_run_start = [&](const PlannedRun& run, int) {
    for (const std::string& name : finished) {
      const std::string path = RunFiles(Dir("r") + "/" + name).finals;
      EXPECT_TRUE(fs::exists(path)) << path << " when " << run.name << " started";
      if (fs::exists(path)) finals_then[name] = ReadFile(path);
    }
    finished.push_back(run.name);
  };
  Reproduction(Tiny(), Dir("r"), StartMode::kNew).Run(Threads(2), observer, 1);
  EXPECT_EQ(finals_then.size(), 2u);
  for (const auto& [name, text] : finals_then) {
    EXPECT_EQ(ReadFile(RunFiles(Dir("r") + "/" + name).finals), text) << name;
  }
}

// An experiment continues on another machine from its committed runs (kept
// without their evaluations): the missing runs are made, the kept ones are
// not touched, and the statistics are those of the reproduction made at once.
TEST_F(ReproductionTest, ContinuesFromFinishedRunsKeptWithoutTheirEvaluations) {
  ReproductionConfig c = Tiny();
  c.replicates = 2;
  Reproduction(c, Dir("at_once"), StartMode::kNew).Run(Threads(2));

  Reproduction(Tiny(), Dir("first"), StartMode::kNew).Run(Threads(2));
  fs::create_directory(Dir("continued"));
  for (const PlannedRun& run : PlanRuns(Tiny())) {
    const RunFiles from(Dir("first") + "/" + run.name), to(Dir("continued") + "/" + run.name);
    fs::create_directory(to.dir);
    for (const std::string RunFiles::*file : RunFiles::All()) {
      if (file != &RunFiles::evaluations && fs::exists(from.*file)) fs::copy_file(from.*file, to.*file);
    }
  }
  std::vector<std::string> started;
  ReproductionObserver observer;
  observer.on_run_start = [&](const PlannedRun& run, int completed) {
    if (completed == 0) started.push_back(run.name);
  };
  Reproduction(c, Dir("continued"), StartMode::kResume).Run(Threads(2), observer);
  std::sort(started.begin(), started.end());
  EXPECT_EQ(started, (std::vector<std::string>{"free-2", "performance-2", "time-2"}));
  EXPECT_FALSE(fs::exists(RunFiles(Dir("continued") + "/free-1").evaluations));
  EXPECT_EQ(ReadFile(ReproductionFiles(Dir("continued")).manifest),
            ReadFile(ReproductionFiles(Dir("at_once")).manifest));
}

}  // namespace
}  // namespace walkers
