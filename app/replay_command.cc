// walkers replay: a picture of one genome's walk, animated (HTML) or as a filmstrip (SVG).
#include <cstdio>
#include <filesystem>
#include <memory>

#include "app/commands.h"
#include "app/validators.h"
#include "app/replay.h"
#include "control/genome.h"
#include "control/walk_record.h"
#include "files/durable_file.h"
#include "files/errors.h"

namespace walkers::app {
namespace {

struct ReplayOptions {
  std::string genome_path;
  std::string preset = "original";
  std::string out;
  bool force = false;
};

int RunReplay(const ReplayOptions& opt) {
  const std::string extension = std::filesystem::path(opt.out).extension().string();
  if (extension != ".html" && extension != ".svg") {
    throw InputError("--out " + opt.out + ": the file must end in .html (animation) or .svg (filmstrip)");
  }
  CheckOutputFile("--out", opt.out, opt.force, {{"--genome", opt.genome_path}});
  const Genome genome = LoadGenome(opt.genome_path);
  const Preset preset = PresetByName(opt.preset);
  const std::string title = std::filesystem::path(opt.genome_path).filename().string() + ", preset " + preset.name;
  const RecordedWalk walk = RecordWalk(genome, preset, title);

  WriteFileAtomically(opt.out, extension == ".html" ? ReplayHtml(walk.json) : FilmstripSvg(walk.json));
  std::printf("%s: %s walk, fitness %.4f\n", opt.out.c_str(), GaitName(walk.result.gait), walk.result.fitness);
  return 0;
}

}  // namespace

void AddReplayCommand(CLI::App& app, Command* selected) {
  auto opt = std::make_shared<ReplayOptions>();
  CLI::App* sub = app.add_subcommand("replay", "Picture a genome's walk: an HTML animation or an SVG filmstrip");
  sub->add_option("--genome", opt->genome_path, "Genome file (JSON)")->required()->check(CLI::ExistingFile);
  AddPresetOption(sub, &opt->preset);
  sub->add_option("--out", opt->out, "walk.html (animation) or walk.svg (filmstrip)")->required();
  AddForceOption(sub, &opt->force, "the --out file");
  sub->callback([opt, selected] { *selected = [opt] { return RunReplay(*opt); }; });
}

}  // namespace walkers::app
