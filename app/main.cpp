// sedem: the command line. Parsing and wiring only; the work is in core/ and render/.
#include <CLI/CLI.hpp>
#include <QGuiApplication>

#include "app/batch_command.h"
#include "app/exit_codes.h"
#include "app/qt_platform.h"
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
  run_cmd->add_option("scene", run_options.scene, "Scene file (TOML)")->required();
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

  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = cli.exit(e);
    return code == 0 ? exit_code::ok : exit_code::usage;
  }

  use_offscreen_platform();
  QGuiApplication qt(argc, argv);
  if (run_cmd->parsed()) return run(run_options);
  if (batch_cmd->parsed()) return batch(batch_options);
  if (render_cmd->parsed()) return render_runs(render_options);
  return exit_code::usage;
}
