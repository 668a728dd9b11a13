// The validation report: reads the run folders scripts/validate.sh made and writes the
// generated parts of docs/validation.md (per sample: wall time, particles, particle-steps/s,
// error and bias per test; compute cost against the paper's; the paper's conclusions, each
// with the numbers that support or contradict it). Prints one verdict line per conclusion.
//
//   sedem_validation_report report --runs DIR... [--reduced DIR...] [--weighting DIR...]
//                                  [--depth DIR...] [--early-s S] [--machine TEXT]
//                                  [--update docs/validation.md]
//   sedem_validation_report variant RUN_DIR VARIANT_DIR --set key=value...
#include <CLI/CLI.hpp>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "bench/validation/markdown.h"
#include "bench/validation/report.h"
#include "bench/validation/run_folder.h"

namespace {

using namespace sedem::validation;
namespace fs = std::filesystem;

// The folders that can be read; a run that failed before writing its results is named and
// left out, so that one failed run of many does not lose the report.
std::vector<RunFolder> read_all(const std::vector<std::string>& dirs) {
  std::vector<RunFolder> runs;
  for (const auto& d : dirs) {
    try {
      runs.push_back(read_run_folder(d));
    } catch (const std::exception& e) {
      std::fprintf(stderr, "sedem_validation_report: left out: %s\n", e.what());
    }
  }
  return runs;
}

void update(const fs::path& file, const Report& report) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot read it");
  std::stringstream text;
  text << in.rdbuf();
  std::string doc = text.str();
  for (const auto& s : report.sections) doc = replace_generated(doc, s.name, s.markdown);
  std::ofstream out(file);
  out << doc;
  if (!out) throw std::runtime_error(file.string() + ": cannot write it");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App cli{"sedem validation report: the paper's conclusions against sedem's runs"};
  cli.require_subcommand(1);

  std::vector<std::string> runs, reduced, weighting, depth;
  ReportInputs in;
  std::string doc;
  auto* report_cmd = cli.add_subcommand("report", "Read run folders, print the verdicts");
  report_cmd->add_option("--runs", runs, "The five samples' run folders")->required();
  report_cmd->add_option("--reduced", reduced, "The same scenes run with fewer particles");
  report_cmd->add_option("--weighting", weighting, "Runs with another weighting scheme");
  report_cmd->add_option("--depth", depth, "Runs read again at other instrument depths");
  report_cmd->add_option("--early-s", in.early_s, "The early part: readings up to this time, s")
      ->capture_default_str();
  report_cmd->add_option("--machine", in.machine, "Where the runs were made");
  report_cmd->add_option("--update", doc,
                         "Rewrite the generated parts of this markdown file (else print them)");

  std::string run_dir, variant_dir;
  std::vector<std::string> sets;
  auto* variant_cmd = cli.add_subcommand(
      "variant", "A run folder for other instrument settings over the same particle files");
  variant_cmd->add_option("run", run_dir, "The run folder")->required();
  variant_cmd->add_option("variant", variant_dir, "The new folder")->required();
  variant_cmd->add_option("--set", sets, "key=value for the scene (repeatable)")->required();
  CLI11_PARSE(cli, argc, argv);

  try {
    if (variant_cmd->parsed()) {
      make_variant(run_dir, variant_dir, sets);
      return 0;
    }
    in.runs = read_all(runs);
    if (in.runs.empty()) throw std::runtime_error("none of the --runs folders can be read");
    in.reduced = read_all(reduced);
    in.weighting = read_all(weighting);
    in.depth = read_all(depth);
    const Report report = build_report(in);
    if (doc.empty()) {
      for (const auto& s : report.sections)
        std::printf("<!-- %s -->\n%s\n", s.name.c_str(), s.markdown.c_str());
    } else {
      update(doc, report);
      std::printf("updated %s\n", doc.c_str());
    }
    for (const auto& c : report.checks) std::printf("%s\n", verdict_line(c).c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sedem_validation_report: %s\n", e.what());
    return 1;
  }
  return 0;
}
