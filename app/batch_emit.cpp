#include "app/batch_emit.h"

#include <algorithm>
#include <cstdio>
#include <set>
#include <system_error>

#include "app/batch_plan_file.h"
#include "app/batch_scripts.h"
#include "app/exit_codes.h"
#include "app/run_folder.h"
#include "app/run_preflight.h"
#include "core/scene/scene_loader.h"
#include "render/atomic_write.h"

namespace sedem::app {
namespace fs = std::filesystem;

namespace {

struct Resolved {
  std::vector<std::string> scenes;  // each run's tasks/RUN.toml
  std::size_t largest_bytes = 0;    // the largest run's memory estimate
};

// The TOML a task runs: where it comes from, then every key of the scene as resolved.
std::string task_scene(const BatchRun& r, Scene& scene) {
  std::string from = r.scene;
  for (const auto& o : r.overrides) from += " --set " + o;
  std::replace(from.begin(), from.end(), '\n', ' ');
  return "# " + r.folder + ": one run of a batch, written by `sedem batch --emit` (sedem " +
         SEDEM_VERSION + ") from\n#   " + from +
         "\n# Every key as resolved: `sedem run` of this file is that run, bit for bit.\n" +
         resolved_toml(scene);
}

// Every run's scene, loaded and resolved; throws SceneError naming the file and the key.
Resolved resolve_scenes(const std::vector<BatchRun>& runs) {
  Resolved out;
  for (const auto& r : runs) {
    Scene scene = load_scene(r.scene, r.overrides);
    out.largest_bytes = std::max(out.largest_bytes, estimate_run_bytes(scene));
    out.scenes.push_back(task_scene(r, scene));
  }
  return out;
}

void write_text(const fs::path& file, const std::string& text, bool executable) {
  write_atomically(file, [&](std::ostream& out) { out << text; });
  if (executable)
    fs::permissions(file, fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec,
                    fs::perm_options::add);
}

// Scenes of an earlier emit into the same folder that this plan no longer has: a task list
// and its scenes always agree.
void remove_stale_scenes(const fs::path& tasks, const std::vector<BatchRun>& runs) {
  std::set<std::string> wanted;
  for (const auto& r : runs) wanted.insert(r.folder + ".toml");
  for (const auto& e : fs::directory_iterator(tasks))
    if (e.is_regular_file() && e.path().extension() == ".toml" &&
        !wanted.count(e.path().filename().string()))
      fs::remove(e.path());
}

// Why the batch's folder cannot be named on an #SBATCH line ("" if it can): those lines are
// not read by a shell, so nothing in them can be quoted, and % starts Slurm's own patterns.
std::string slurm_path_error(const fs::path& dir) {
  const std::string text = dir.string();
  if (text.find_first_of(" \t\n'\"%\\") == std::string::npos) return "";
  return dir.string() +
         ": a folder for Slurm's #SBATCH lines cannot hold a space, a quote, a backslash or %";
}

void print_next_steps(const BatchOptions& options, const TaskScripts& t, std::size_t runs,
                      const std::string& mem) {
  const fs::path& dir = t.dir;
  if (options.scheduler == "slurm") {
    std::printf(
        "sedem: %zu runs written for Slurm into %s: sedem.sbatch, a job array of %zu tasks "
        "(%d CPU, %s, %s each)\n"
        "  submit:  %s\n"
        "  or:      sbatch %s, then once every task has ended: %s\n",
        runs, dir.c_str(), runs, options.slurm.cpus, mem.c_str(), options.slurm.time.c_str(),
        shell_quote((dir / "submit.sh").string()).c_str(),
        shell_quote((dir / "sedem.sbatch").string()).c_str(), gather_command(t).c_str());
  } else {
    std::printf(
        "sedem: %zu runs written for GNU parallel into %s: parallel.txt, one line per run\n"
        "  run:  %s [parallel's options, e.g. --sshlogin 4/node1,4/node2,: --env SEDEM]\n"
        "  or:   parallel < %s, then: %s\n",
        runs, dir.c_str(), shell_quote((dir / "parallel.sh").string()).c_str(),
        shell_quote((dir / "parallel.txt").string()).c_str(), gather_command(t).c_str());
  }
}

}  // namespace

int emit_batch(const BatchOptions& options, const std::vector<BatchRun>& runs) {
  if (options.scheduler == "slurm") {
    if (const std::string error = slurm_options_error(options.slurm); !error.empty()) {
      std::fprintf(stderr, "sedem: %s\n", error.c_str());
      return exit_code::usage;
    }
    if (options.jobs_given) {
      std::fprintf(stderr,
                   "sedem: --jobs goes with a batch run here or --emit parallel; a Slurm task's "
                   "cores are --slurm-cpus\n");
      return exit_code::usage;
    }
  }
  if (options.scheduler == "parallel") {
    const SlurmOptions defaults;
    const SlurmOptions& given = options.slurm;
    if (given.time != defaults.time || !given.mem.empty() || given.cpus != defaults.cpus ||
        !given.partition.empty() || !given.account.empty()) {
      std::fprintf(stderr,
                   "sedem: the --slurm-* options go with --emit slurm; GNU parallel's runs take "
                   "one core each (--jobs: runs at once)\n");
      return exit_code::usage;
    }
  }
  Resolved resolved;
  try {
    resolved = resolve_scenes(runs);
  } catch (const SceneError& e) {
    std::fprintf(stderr, "sedem: invalid scene: %s\n", e.what());
    return exit_code::invalid_scene;
  }

  TaskScripts t;
  std::error_code ec;
  t.dir = fs::absolute(options.out_dir, ec).lexically_normal();
  if (t.dir.has_filename() == false) t.dir = t.dir.parent_path();  // "out/x/" -> "out/x"
  t.sedem = fs::read_symlink("/proc/self/exe", ec);
  t.name = "sedem-" + safe_folder_name(fs::path(runs.front().scene).stem().string());
  t.overwrite = options.overwrite;
  t.set_threads = std::none_of(runs.begin(), runs.end(), [](const BatchRun& r) {
    return std::any_of(r.overrides.begin(), r.overrides.end(),
                       [](const std::string& o) { return o.rfind("integrator.threads=", 0) == 0; });
  });
  if (options.scheduler == "slurm")
    if (const std::string error = slurm_path_error(t.dir); !error.empty()) {
      std::fprintf(stderr, "sedem: %s\n", error.c_str());
      return exit_code::output_unwritable;
    }
  const std::string mem =
      options.slurm.mem.empty() ? slurm_memory_for(resolved.largest_bytes) : options.slurm.mem;

  try {
    const fs::path tasks = t.dir / kBatchTasksFolder;
    fs::create_directories(tasks / "logs");
    remove_stale_scenes(tasks, runs);
    for (std::size_t i = 0; i < runs.size(); ++i)
      write_text(tasks / (runs[i].folder + ".toml"), resolved.scenes[i], false);
    write_text(tasks / "runs.txt", task_list(runs), false);
    write_text(tasks / "run_task.sh", task_script(t), true);
    if (options.scheduler == "slurm") {
      write_text(t.dir / "sedem.sbatch", slurm_script(t, runs.size(), options.slurm, mem), true);
      write_text(t.dir / "submit.sh", slurm_submit_script(t, options.slurm), true);
    } else {
      write_text(t.dir / "parallel.txt", parallel_commands(t, runs), false);
      write_text(t.dir / "parallel.sh", parallel_script(t, options.jobs_given ? options.jobs : 0),
                 true);
    }
    BatchOptions plan = options;
    plan.out_dir = t.dir.string();
    write_plan_file(plan, runs);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sedem: cannot write the batch's tasks: %s\n", e.what());
    return exit_code::output_unwritable;
  }
  // A folder that holds a run already keeps it: its task goes on with it, or leaves it if it
  // is complete, whatever this emit's scene says, unless --overwrite.
  const auto held = std::count_if(runs.begin(), runs.end(), [&](const BatchRun& r) {
    return fs::exists(t.dir / r.folder / "run.json");
  });
  if (held > 0 && !options.overwrite)
    std::fprintf(stderr,
                 "sedem: warning: %td of the %zu run folders hold a run already: their tasks go "
                 "on with it, or leave it if it is complete (--overwrite: the tasks replace "
                 "them)\n",
                 held, runs.size());
  if (!options.quiet) print_next_steps(options, t, runs.size(), mem);
  return exit_code::ok;
}

}  // namespace sedem::app
