// sedem: the command line. Parsing and wiring only; the work is in core/ and render/.
#include <CLI/CLI.hpp>

#include <cstdlib>
#include <iostream>

#include "app/qt_platform.h"
#include "app/run_command.h"

int main(int argc, char** argv) {
  sedem::app::use_offscreen_platform();
  CLI::App cli{
      "sedem - DEM simulation of the hydrometer, buoyancy and pipette sedimentation tests"};
  cli.require_subcommand(1);
  cli.set_version_flag("--version", SEDEM_VERSION);

  sedem::app::RunOptions run;
  auto* run_cmd = cli.add_subcommand("run", "Simulate a scene and write its outputs");
  run_cmd->add_option("scene", run.scene, "Scene file (TOML)")
      ->required()
      ->check(CLI::ExistingFile);
  run_cmd->add_option("--out", run.out_dir, "Output folder")->capture_default_str();
  run_cmd->add_option("--set", run.overrides, "Override a scene key: key=value (repeatable)");
  run_cmd->add_flag("-q,--quiet", run.quiet, "Print only warnings and errors");

  CLI11_PARSE(cli, argc, argv);
  if (run_cmd->parsed()) return sedem::app::run(run, argc, argv);
  return EXIT_FAILURE;
}
