// sedem: the command line. Parsing and wiring only; the work is in core/ and render/.
#include <vtkObject.h>
#include <CLI/CLI.hpp>
#include <QGuiApplication>

#include <algorithm>
#include <cstdio>
#include <new>
#include <string>
#include <vector>

#include "app/batch_command.h"
#include "app/batch_gather.h"
#include "app/bench_command.h"
#include "app/design_command.h"
#include "app/exit_codes.h"
#include "app/invert_command.h"
#include "app/paraview_command.h"
#include "app/qt_platform.h"
#include "app/reduce_command.h"
#include "app/render_command.h"
#include "app/run_command.h"
#include "core/scene/edit_distance.h"

namespace {

// "; did you mean 'run'?" when a command is close to `typed` (at most two edits, or the same
// letters in another order), else "".
std::string suggestion(const std::string& typed, const std::vector<std::string>& names) {
  std::string best;
  std::size_t best_distance = 3;
  for (const auto& name : names) {
    std::string a = typed, b = name;
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    const std::size_t d = a == b ? 1 : sedem::edit_distance(typed, name);
    if (d < best_distance) best = name, best_distance = d;
  }
  return best.empty() ? "" : "; did you mean '" + best + "'?";
}

// The options `reduce` and `invert` share for a laboratory's files (docs/lab.md); `whole`
// says what the sieve analysis makes of the output.
void add_lab_input_options(CLI::App* command, sedem::app::LabInputOptions& lab,
                           const std::string& whole) {
  command->add_option("--sheet", lab.sheet,
                      "The readings' sheet of an .xlsx workbook (default: the first)");
  auto* sieve = command->add_option("--sieve", lab.sieve,
                                    "The sample's sieve analysis (ASTM D6913): opening (mm) and "
                                    "mass retained (g) per sieve, a pan and a total row; " +
                                        whole);
  // Without --sieve these would be ignored: refused instead.
  command
      ->add_option("--sieve-sheet", lab.sieve_sheet,
                   "The sieve analysis' sheet of an .xlsx workbook (default: the first)")
      ->needs(sieve);
  command
      ->add_option("--sieve-total-g", lab.sieve_total_g,
                   "The sample's total dry mass, g (default: the sieve file's total row, or "
                   "the sum of its sieves and pan)")
      ->check(CLI::Range(1e-3, 1e6))
      ->needs(sieve);
  command
      ->add_option("--separating-sieve-mm", lab.separating_sieve_mm,
                   "The sieve the tested specimen passed, mm (No. 10: 2; No. 200: 0.075)")
      ->check(CLI::Range(0.02, 100.0))
      ->capture_default_str()
      ->needs(sieve);
}

}  // namespace

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
  run_cmd->add_option("--out", run_options.out_dir,
                      "Output folder (default: out/<scene name>); it must be empty, or hold "
                      "the outputs of a run that --overwrite replaces");
  run_cmd->add_flag("--overwrite", run_options.overwrite,
                    "Replace the run that the output folder holds (its series, frames, "
                    "figures, readings, report)");
  run_cmd->add_option("--set", run_options.overrides,
                      "Override a scene key, key=value (repeatable)");
  run_cmd->add_flag("-q,--quiet", run_options.quiet, "Print only warnings and errors");

  BatchOptions batch_options;
  std::string gather_dir;
  auto* batch_cmd = cli.add_subcommand(
      "batch",
      "Run several scenes, or one scene over a sweep of a key, each into a sub-folder; or write "
      "them as tasks for Slurm or GNU parallel (--emit) and summarise them when done (--gather)");
  auto* batch_scenes = batch_cmd->add_option("scenes", batch_options.scenes, "Scene files (TOML)");
  auto* batch_sweep = batch_cmd->add_option(
      "--sweep", batch_options.sweep,
      "One run per value: key=v1,v2,... (e.g. sample.simulated_count=1e3,1e4)");
  auto* batch_out = batch_cmd->add_option("--out", batch_options.out_dir, "Parent output folder")
                        ->capture_default_str();
  auto* batch_set =
      batch_cmd->add_option("--set", batch_options.overrides, "Override a key in every run");
  auto* batch_jobs =
      batch_cmd
          ->add_option("-j,--jobs", batch_options.jobs,
                       "Runs at once, each given its share of the cores (integrator.threads); "
                       "with --emit parallel, parallel's --jobs (default: one per core)")
          ->check(CLI::Range(1, 256))
          ->capture_default_str();
  auto* batch_seeds =
      batch_cmd->add_option("--seeds", batch_options.seeds,
                            "Runs per scene (and swept value) differing only in sample.seed, "
                            "1 to 10000; from 2, summary_stats.csv: mean and 95 % interval");
  auto* batch_seed0 =
      batch_cmd->add_option("--seed0", batch_options.seed0,
                            "The first seed of --seeds (default 1): seed0, seed0 + 1, ...");
  auto* batch_overwrite =
      batch_cmd->add_flag("--overwrite", batch_options.overwrite,
                          "Replace the runs that the sub-folders hold (with --emit: each task "
                          "replaces its folder's run instead of going on with it)");
  batch_cmd->add_flag("-q,--quiet", batch_options.quiet, "Print only warnings and errors");
  auto* batch_emit =
      batch_cmd
          ->add_option("--emit", batch_options.scheduler,
                       "Run nothing: write the runs into --out as tasks for a scheduler, each "
                       "run's resolved scene beside them: slurm (a job array, sedem.sbatch and "
                       "submit.sh) or parallel (GNU parallel's parallel.txt and parallel.sh)")
          ->check(CLI::IsMember({"slurm", "parallel"}));
  auto* batch_gather = batch_cmd->add_option(
      "--gather", gather_dir,
      "Summarise a batch written by --emit in this folder once its tasks have ended: "
      "summary.csv, summary_stats.csv, figures, index.html; runs not complete are listed");
  batch_cmd
      ->add_option("--slurm-time", batch_options.slurm.time,
                   "With --emit slurm: each task's time limit (minutes, HH:MM:SS, D-HH:MM:SS)")
      ->capture_default_str()
      ->needs(batch_emit);
  batch_cmd
      ->add_option("--slurm-mem", batch_options.slurm.mem,
                   "With --emit slurm: each task's memory, e.g. 800M, 4G (default: the largest "
                   "run's estimate with a margin)")
      ->needs(batch_emit);
  batch_cmd
      ->add_option("--slurm-cpus", batch_options.slurm.cpus,
                   "With --emit slurm: each task's CPUs, its run's integrator.threads")
      ->capture_default_str()
      ->needs(batch_emit);
  batch_cmd
      ->add_option("--slurm-partition", batch_options.slurm.partition,
                   "With --emit slurm: the partition (default: the cluster's)")
      ->needs(batch_emit);
  batch_cmd
      ->add_option("--slurm-account", batch_options.slurm.account,
                   "With --emit slurm: the account charged (default: the user's)")
      ->needs(batch_emit);
  // A gathered batch is the one its plan says: nothing of the command line changes it.
  for (auto* option : {batch_scenes, batch_sweep, batch_out, batch_set, batch_jobs, batch_seeds,
                       batch_seed0, batch_overwrite, batch_emit})
    batch_gather->excludes(option);
  batch_cmd->callback([&] {
    if (batch_options.scenes.empty() && gather_dir.empty())
      throw CLI::RequiredError("scene files, or --gather DIR");
    batch_options.jobs_given = batch_jobs->count() > 0;
  });

  RenderOptions render_options;
  auto* render_cmd = cli.add_subcommand(
      "render",
      "Draw a run's figures, frames and report.html again from its saved files, without "
      "simulating");
  render_cmd->add_option("runs", render_options.run_dirs, "Run folders (written by sedem run)")
      ->required();
  render_cmd
      ->add_option("--out", render_options.out_dir,
                   "Where figures shared by several runs go (one panel per run)")
      ->capture_default_str();
  render_cmd->add_flag("-q,--quiet", render_options.quiet, "Print only warnings and errors");
  render_cmd->add_flag("--partial", render_options.partial,
                       "Redraw a run that did not complete (stopped, failed or killed): its "
                       "files stop where it did");

  ParaviewOptions paraview_options;
  auto* paraview_cmd = cli.add_subcommand(
      "paraview",
      "Write RUN_DIR/sedem.pvsm, a ParaView state that opens the run as the paper shows it "
      "(runs ParaView's pvpython)");
  paraview_cmd->add_option("run", paraview_options.run_dir, "Run folder (written by sedem run)")
      ->required();
  paraview_cmd->add_option("--pvpython", paraview_options.pvpython,
                           "ParaView's pvpython (default: SEDEM_PVPYTHON, then pvpython on PATH)");
  paraview_cmd->add_option("--time", paraview_options.time,
                           "Simulated time shown, s (default: the last)");
  paraview_cmd->add_option("--screenshot", paraview_options.screenshot,
                           "Also save the state's picture as this PNG");
  paraview_cmd->add_flag("-q,--quiet", paraview_options.quiet, "Print only warnings and errors");

  ReduceOptions reduce_options;
  auto* reduce_cmd = cli.add_subcommand(
      "reduce",
      "Reduce laboratory hydrometer readings (152H) to a grading curve, ASTM D7928 or D422");
  reduce_cmd
      ->add_option("readings", reduce_options.readings,
                   "CSV (',' or ';' with decimal commas), tab-separated text or .xlsx with "
                   "columns time_min, reading_g_per_l, temperature_c and optionally "
                   "composite_correction_g_per_l, meniscus_correction_g_per_l, or the same in "
                   "the lab's words and units: time (min), R (g/L), T (°C), ...")
      ->required();
  add_lab_input_options(reduce_cmd, reduce_options.lab, "the output is then the whole curve");
  reduce_cmd->add_option("--report", reduce_options.report,
                         "Write a one-page lab report (HTML) and its figure beside it");
  reduce_cmd->add_option("--out", reduce_options.out, "Output CSV (default: standard output)");
  reduce_cmd
      ->add_option("--method", reduce_options.method,
                   "d7928 (ASTM D7928) or d422 (ASTM D422, withdrawn in 2016)")
      ->check(CLI::IsMember({"d422", "d7928"}))
      ->capture_default_str();
  reduce_cmd->add_option("--gs", reduce_options.specific_gravity, "Specific gravity of the solids")
      ->check(CLI::Range(1.01, 10.0))
      ->capture_default_str();
  reduce_cmd->add_option("--mass-g", reduce_options.dry_mass_g, "Oven-dry mass of the specimen, g")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  reduce_cmd->add_option("--volume-ml", reduce_options.volume_ml, "Suspension volume, mL")
      ->check(CLI::Range(10.0, 10000.0))
      ->capture_default_str();

  InvertOptions invert_options;
  auto* invert_cmd = cli.add_subcommand(
      "invert",
      "From a laboratory's readings back to the grading curve: the curve whose simulated test "
      "reproduces them, with an uncertainty band, beside the standard reduction");
  auto* invert_readings = invert_cmd->add_option(
      "readings", invert_options.readings,
      "CSV, tab-separated text or .xlsx: hydrometer as for reduce; buoyancy time_min, "
      "apparent_mass_g; pipette time_min, dry_mass_g (or in the lab's words and units: "
      "time (s), apparent mass (g), dry mass (mg), ...)");
  add_lab_input_options(invert_cmd, invert_options.lab,
                        "whole_curve.csv then holds the whole grading curve");
  auto* invert_run =
      invert_cmd
          ->add_option("--run", invert_options.run,
                       "Instead of READINGS: a run folder, whose readings (rounded to the "
                       "resolution), scene and true curve are used")
          ->excludes(invert_readings);
  invert_cmd
      ->add_flag("--partial", invert_options.partial,
                 "With --run: accept a run that did not complete (its readings stop where it "
                 "did)")
      ->needs(invert_run);
  invert_cmd->add_option("--test", invert_options.test, "hydrometer, buoyancy or pipette")
      ->check(CLI::IsMember({"hydrometer", "buoyancy", "pipette"}))
      ->capture_default_str();
  invert_cmd
      ->add_option("--scene", invert_options.scene,
                   "Set-up from a scene (cylinder, fluid, grains, mass, instruments)")
      ->excludes(invert_run);
  invert_cmd->add_option("--out", invert_options.out, "Output folder")->capture_default_str();
  invert_cmd
      ->add_option("--method", invert_options.method,
                   "The 152H's standard reduction: d7928 (ASTM D7928) or d422 (ASTM D422)")
      ->check(CLI::IsMember({"d422", "d7928"}))
      ->capture_default_str();
  invert_cmd->add_option("--gs", invert_options.specific_gravity,
                         "Specific gravity of the solids (default 2.65)");
  invert_cmd->add_option("--mass-g", invert_options.dry_mass_g, "Dry mass in the cylinder, g (50)");
  invert_cmd->add_option("--volume-ml", invert_options.volume_ml, "Suspension volume, mL (1000)");
  invert_cmd->add_option("--area-cm2", invert_options.area_cm2,
                         "Cylinder's inside cross-section, cm^2 (27.8)");
  invert_cmd->add_option("--depth-cm", invert_options.depth_cm,
                         "Depth of the sphere's or pipette's centre, cm (0.3 of the height)");
  invert_cmd->add_option("--temperature-c", invert_options.temperature_c,
                         "Water temperature for the sphere and pipette without a scene (20)");
  invert_cmd->add_option("--liquid-density", invert_options.liquid_density,
                         "Density of the clear liquid (water and dispersant), kg/m^3 (default: "
                         "water at the temperature)");
  invert_cmd->add_option("--blank-g", invert_options.blank_g,
                         "Sphere: its apparent mass in the clear liquid, g (sets the liquid's "
                         "density)");
  invert_cmd->add_option("--pipette-ml", invert_options.pipette_ml,
                         "Pipette: the volume it draws, mL (default 35, or the scene's)");
  invert_cmd
      ->add_option("--resolution", invert_options.resolution,
                   "Reading resolution in the reading's unit (0: 1 g/L, 0.001 g, 0.0001 g)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  invert_cmd
      ->add_option("--refine", invert_options.refine,
                   "Grid nodes between two readings' diameters (0 to 6)")
      ->capture_default_str();
  invert_cmd->add_option("--replicas", invert_options.replicas, "Samples for the band (0: none)")
      ->check(CLI::Range(0, 100000))
      ->capture_default_str();
  invert_cmd->add_option("--coverage", invert_options.coverage, "Coverage of the band")
      ->capture_default_str();
  invert_cmd->add_option("--seed", invert_options.seed, "Seed of the band's noise")
      ->capture_default_str();
  invert_cmd->add_flag("-q,--quiet", invert_options.quiet, "Print only warnings and errors");

  DesignCommandOptions design_options;
  auto* design_cmd = cli.add_subcommand(
      "design",
      "Design a test's reading schedule: the times (and depth) whose curve is closest to the "
      "scene's true curve, beside the standard's, from the reference solution and a DEM run");
  design_cmd->add_option("scene", design_options.scene, "Scene file (TOML)")->required();
  design_cmd->add_option("--test", design_options.test, "hydrometer, buoyancy or pipette")
      ->required();
  design_cmd->add_option("--readings", design_options.readings,
                         "Readings of the designed schedule (default: the standard's count)");
  design_cmd->add_option("--out", design_options.out,
                         "Output folder (default out/design/<scene>_<test>)");
  design_cmd->add_option("--set", design_options.overrides, "Override a scene key");
  design_cmd->add_option("--dem-count", design_options.dem_count,
                         "Particles of the confirming DEM run (default: the scene's; 0: none)");
  design_cmd
      ->add_option("--sizes", design_options.sizes,
                   "Sizes the grading curve is cut into for the reference and the DEM run")
      ->capture_default_str();
  design_cmd->add_flag("-q,--quiet", design_options.quiet, "Print only warnings and errors");

  BenchOptions bench_options;
  auto* bench_cmd = cli.add_subcommand(
      "bench",
      "Run a benchmark: engine (throughput, memory, stability), accuracy (run time "
      "against error for every sample), speedup (the exponential against the explicit integrator, "
      "side by "
      "side) or scale (the whole test of every sample against particle count); arguments "
      "after -- go to it");
  bench_cmd->add_option("which", bench_options.which, "engine, accuracy, speedup or scale")
      ->check(CLI::IsMember({"engine", "accuracy", "speedup", "scale"}))
      ->capture_default_str();
  bench_cmd->add_option("args", bench_options.args, "Arguments for the benchmark (after --)");

  std::vector<std::string> names;
  for (const auto* sub : cli.get_subcommands({})) names.push_back(sub->get_name());
  if (argc > 1 && argv[1][0] != '-' &&
      std::find(names.begin(), names.end(), argv[1]) == names.end()) {
    std::fprintf(stderr, "sedem: '%s' is not a command%s\nCommands: ", argv[1],
                 suggestion(argv[1], names).c_str());
    for (std::size_t i = 0; i < names.size(); ++i)
      std::fprintf(stderr, "%s%s", i ? ", " : "", names[i].c_str());
    std::fprintf(stderr, " (sedem --help)\n");
    return exit_code::usage;
  }

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
  try {
    if (run_cmd->parsed()) return run(run_options);
    if (batch_cmd->parsed())
      return gather_dir.empty() ? batch(batch_options)
                                : gather_batch(gather_dir, batch_options.quiet);
    if (render_cmd->parsed()) return render_runs(render_options);
    if (paraview_cmd->parsed()) return paraview_state(paraview_options);
    if (reduce_cmd->parsed()) return reduce(reduce_options);
    if (invert_cmd->parsed()) return invert(invert_options);
    if (design_cmd->parsed()) return design(design_options);
  } catch (const std::bad_alloc&) {
    // Out of memory anywhere a command did not handle it: a message, never an abort.
    std::fputs("sedem: out of memory\n", stderr);
    return exit_code::engine_failure;
  }
  return exit_code::usage;
}
