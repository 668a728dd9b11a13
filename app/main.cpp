// sedem: the command line. Parsing and wiring only; the work is in core/ and render/.
#include <vtkObject.h>
#include <CLI/CLI.hpp>
#include <QGuiApplication>

#include "app/batch_command.h"
#include "app/bench_command.h"
#include "app/exit_codes.h"
#include "app/qt_platform.h"
#include "app/reduce_command.h"
#include "app/render_command.h"
#include "app/run_command.h"

int main(int argc, char** argv) {
  using namespace sedem::app;
  CLI::App cli{
      "sedem - DEM simulation of the hydrometer, buoyancy and pipette sedimentation tests"};
  cli.require_subcommand(1);
  cli.set_version_flag("--version", SEDEM_VERSION);

  RunOptions run_options;
  auto* run_cmd = cli.add_subcommand("run", "Simulate a scene and write its outputs");
  auto* scene_opt = run_cmd->add_option("scene", run_options.scene, "Scene file (TOML)");
  auto* resume_opt = run_cmd->add_option(
      "--resume", run_options.resume_dir,
      "Go on with the run stopped by Ctrl-C or SIGTERM in this folder, from its checkpoint");
  scene_opt->excludes(resume_opt);
  run_cmd->callback([&] {
    if (run_options.scene.empty() && run_options.resume_dir.empty())
      throw CLI::RequiredError("a scene file or --resume DIR");
  });
  run_cmd->add_option("--out", run_options.out_dir, "Output folder")->capture_default_str();
  run_cmd->add_option("--set", run_options.overrides,
                      "Override a scene key, key=value (repeatable)");
  run_cmd->add_flag("-q,--quiet", run_options.quiet, "Print only warnings and errors");

  BatchOptions batch_options;
  auto* batch_cmd = cli.add_subcommand(
      "batch", "Run several scenes, or one scene over a sweep of a key, each into a sub-folder");
  batch_cmd->add_option("scenes", batch_options.scenes, "Scene files (TOML)")->required();
  batch_cmd->add_option("--sweep", batch_options.sweep,
                        "One run per value: key=v1,v2,... (e.g. sample.simulated_count=1e3,1e4)");
  batch_cmd->add_option("--out", batch_options.out_dir, "Parent output folder")
      ->capture_default_str();
  batch_cmd->add_option("--set", batch_options.overrides, "Override a key in every run");
  batch_cmd->add_flag("-q,--quiet", batch_options.quiet, "Print only warnings and errors");

  RenderOptions render_options;
  auto* render_cmd = cli.add_subcommand(
      "render", "Draw a run's figures and frames again from its saved files, without simulating");
  render_cmd->add_option("runs", render_options.run_dirs, "Run folders (written by sedem run)")
      ->required();
  render_cmd
      ->add_option("--out", render_options.out_dir,
                   "Where figures shared by several runs go (one panel per run)")
      ->capture_default_str();
  render_cmd->add_flag("-q,--quiet", render_options.quiet, "Print only warnings and errors");

  ReduceOptions reduce_options;
  auto* reduce_cmd = cli.add_subcommand(
      "reduce", "Reduce laboratory hydrometer readings (152H) to a grading curve, ASTM D422/D7928");
  reduce_cmd
      ->add_option("readings", reduce_options.readings,
                   "CSV with columns time_min, reading_g_per_l, temperature_c and optionally "
                   "composite_correction_g_per_l")
      ->required();
  reduce_cmd->add_option("--out", reduce_options.out, "Output CSV (default: standard output)");
  reduce_cmd->add_option("--method", reduce_options.method, "d422 or d7928")
      ->check(CLI::IsMember({"d422", "d7928"}))
      ->capture_default_str();
  reduce_cmd->add_option("--gs", reduce_options.specific_gravity, "Specific gravity of the solids")
      ->check(CLI::Range(1.01, 10.0))
      ->capture_default_str();
  reduce_cmd->add_option("--mass-g", reduce_options.dry_mass_g, "Oven-dry mass of the specimen, g")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();

  BenchOptions bench_options;
  auto* bench_cmd = cli.add_subcommand(
      "bench",
      "Run a benchmark: engine (throughput, memory, stability), accuracy (run time "
      "against error for every sample), speedup (fast against reference integrator, side by "
      "side) or scale (the whole test of every sample against particle count); arguments "
      "after -- go to it");
  bench_cmd->add_option("which", bench_options.which, "engine, accuracy, speedup or scale")
      ->check(CLI::IsMember({"engine", "accuracy", "speedup", "scale"}))
      ->capture_default_str();
  bench_cmd->add_option("args", bench_options.args, "Arguments for the benchmark (after --)");

  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = cli.exit(e);
    return code == 0 ? exit_code::ok : exit_code::usage;
  }

  if (bench_cmd->parsed()) return bench(bench_options);
  // VTK's own error printing is off: every failure that matters reaches the user as an
  // exception with the file and the reason.
  vtkObject::GlobalWarningDisplayOff();
  use_offscreen_platform();
  QGuiApplication qt(argc, argv);
  if (run_cmd->parsed()) return run(run_options);
  if (batch_cmd->parsed()) return batch(batch_options);
  if (render_cmd->parsed()) return render_runs(render_options);
  if (reduce_cmd->parsed()) return reduce(reduce_options);
  return exit_code::usage;
}
