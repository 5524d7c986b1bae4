// `dynanav simulate`: writes a synthetic RGB-D sequence with exact ground truth (src/sim).
#include <spdlog/spdlog.h>

#include <iostream>
#include <memory>

#include "apps/dynanav/commands.hpp"
#include "core/error.hpp"
#include "sim/simulator.hpp"

namespace dynanav::cli {

namespace {
struct SimulateArgs {
  sim::SimOptions options;
  std::string out;
  std::string scenario;
  bool list = false;
  bool quiet = false;
};

std::string scenarioHelp() {
  std::string text = "scenario:";
  for (const auto& s : sim::scenarioList()) text += "\n    " + s.name + ": " + s.description;
  return text;
}

int simulate(const SimulateArgs& args) {
  if (args.list) {
    for (const auto& s : sim::scenarioList()) std::cout << s.name << "\t" << s.description << "\n";
    return kExitOk;
  }
  if (args.scenario.empty()) throw InputError("--scenario", "required (see --list)");
  if (args.out.empty())
    throw InputError("--out", "required: the folder to write the sequence into");
  sim::SimOptions options = args.options;
  options.scenario = args.scenario;
  sim::Simulator simulator(options);
  spdlog::info("simulate: scenario '{}', seed {}, {} frames at {} fps -> {}", options.scenario,
               options.seed, simulator.frameCount(), options.fps, args.out);
  const sim::WriteStats stats = sim::writeSequence(simulator, args.out);
  spdlog::info("simulate: wrote {} frames in {:.2f} s ({:.1f} frames/s)", stats.frames,
               stats.seconds, stats.frames / std::max(stats.seconds, 1e-9));
  return kExitOk;
}
}  // namespace

void registerSimulate(CLI::App& root, Action& chosen) {
  auto args = std::make_shared<SimulateArgs>();
  auto* sub =
      root.add_subcommand("simulate", "write a synthetic RGB-D sequence with exact ground truth");
  sub->add_option("--scenario", args->scenario, scenarioHelp());
  sub->add_option("--out", args->out,
                  "output folder (TUM layout plus masks/, masks.json, objects_gt.jsonl)");
  sub->add_option("--frames", args->options.frames,
                  "number of frames (default: the scenario's length)")
      ->check(finiteRange(0, 100000));
  sub->add_option("--seed", args->options.seed, "random seed: textures, clothing, sensor noise")
      ->capture_default_str();
  sub->add_option("--fps", args->options.fps, "frame rate")
      ->capture_default_str()
      ->check(finiteRange(1.0, 1000.0));
  sub->add_flag("--noiseless", args->options.noiseless, "exact depth and clean colour (for tests)");
  sub->add_option_function<double>(
         "--rolling-shutter-ms", [args](double ms) { args->options.readout_s = ms * 1e-3; },
         "rolling-shutter readout of the camera (ms; 0 = global shutter, the default); written to "
         "camera.yaml")
      ->check(finiteRange(0.0, 1000.0));
  sub->add_option_function<double>(
         "--exposure-ms", [args](double ms) { args->options.exposure_s = ms * 1e-3; },
         "exposure time of the colour camera (ms; 0 = instantaneous, the default): motion blur, "
         "each row's colour averaged over its exposure")
      ->check(finiteRange(0.0, 1000.0));
  sub->add_flag("!--no-photos", args->options.photos,
                "posters without the opencv-doc example photos");
  sub->add_flag("--list", args->list, "list the scenarios and exit");
  sub->callback([&chosen, args] { chosen = [args] { return simulate(*args); }; });
}

}  // namespace dynanav::cli
