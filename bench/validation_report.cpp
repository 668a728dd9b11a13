// The validation report: reads the run folders scripts/validate.sh made and writes the
// generated parts of docs/validation.md (per sample: wall time, particles, particle-steps/s,
// error and bias per test; compute cost against the paper's; the paper's conclusions, each
// with the numbers that support or contradict it). Prints one verdict line per conclusion.
//
//   sedem_validation_report report --runs DIR... [--reduced DIR...] [--weighting DIR...]
//                                  [--depth DIR...] [--early-s S] [--machine TEXT]
//                                  [--update docs/validation.md]
//   sedem_validation_report variant RUN_DIR VARIANT_DIR --set key=value...
//   sedem_validation_report study --regime LABEL=DIR... [--out DIR] [--early-s S]
//                                 [--update docs/validation.md]
//
// The study decides the conclusions over seeds: each DIR holds seed batches (main/ and,
// optionally, shallow/ and deep/; see bench/validation/study_report.h).
#include <CLI/CLI.hpp>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "bench/validation/markdown.h"
#include "bench/validation/report.h"
#include "bench/validation/run_folder.h"
#include "bench/validation/study_report.h"

namespace {

using namespace sedem::validation;
namespace fs = std::filesystem;

std::vector<RunFolder> read_all(const std::vector<std::string>& dirs) {
  return read_run_folders({dirs.begin(), dirs.end()});
}

void update(const fs::path& file, const std::vector<Section>& sections) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot read it");
  std::stringstream text;
  text << in.rdbuf();
  std::string doc = text.str();
  for (const auto& s : sections) doc = replace_generated(doc, s.name, s.markdown);
  std::ofstream out(file);
  out << doc;
  if (!out) throw std::runtime_error(file.string() + ": cannot write it");
}

// "passing=out/validation/study/passing" -> the label and the folder.
std::pair<std::string, fs::path> split_regime(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
    throw std::invalid_argument("--regime " + text + ": expected LABEL=DIR");
  return {text.substr(0, eq), text.substr(eq + 1)};
}

void run_study(const std::vector<std::string>& regime_args, const fs::path& out, double early_s,
               const std::string& doc) {
  std::vector<StudyRegime> regimes;
  for (const auto& arg : regime_args) {
    const auto [label, dir] = split_regime(arg);
    regimes.push_back(read_regime(label, dir, early_s));
  }
  write_study_files(regimes, out);
  const std::string markdown = study_markdown(regimes);
  if (doc.empty()) {
    std::printf("<!-- study -->\n%s\n", markdown.c_str());
  } else {
    update(doc, {{"study", markdown}});
    std::printf("updated %s\n", doc.c_str());
  }
  std::printf("wrote %s and %s\n", (out / "study.csv").c_str(), (out / "study_seeds.csv").c_str());
  for (const auto& r : regimes)
    for (const auto& c : r.conclusions) std::printf("%s\n", study_line(r, c).c_str());
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

  std::vector<std::string> regimes;
  std::string study_out = "out/validation/study";
  double study_early_s = kStudyEarlyTime;
  std::string study_doc;
  auto* study_cmd = cli.add_subcommand(
      "study", "The paper's conclusions decided over seeds: study.csv, study_seeds.csv");
  study_cmd->add_option("--regime", regimes, "LABEL=DIR, DIR holding main/ [shallow/ deep/]")
      ->required();
  study_cmd->add_option("--out", study_out, "Folder for study.csv and study_seeds.csv")
      ->capture_default_str();
  study_cmd->add_option("--early-s", study_early_s, "The early part: readings up to this time, s")
      ->capture_default_str();
  study_cmd->add_option("--update", study_doc,
                        "Rewrite the generated section study of this markdown file");
  CLI11_PARSE(cli, argc, argv);

  try {
    if (variant_cmd->parsed()) {
      make_variant(run_dir, variant_dir, sets);
      return 0;
    }
    if (study_cmd->parsed()) {
      run_study(regimes, study_out, study_early_s, study_doc);
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
      update(doc, report.sections);
      std::printf("updated %s\n", doc.c_str());
    }
    for (const auto& c : report.checks) std::printf("%s\n", verdict_line(c).c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sedem_validation_report: %s\n", e.what());
    return 1;
  }
  return 0;
}
