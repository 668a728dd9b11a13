// Hostile input against `sedem`: seeded mutations of the shipped scenes, of --set values and
// of laboratory CSVs for `sedem reduce`. Every case must end in exit 2 naming what is wrong,
// or in a run (or reduction) whose outputs hold no NaN or inf; never a crash, a hang or
// another exit code. The test suite runs a few dozen cases (seconds); run it longer with
//   build/bench/sedem_bench_fuzz --cases 2000 --seed 7
// Prints the counts and exits 1 if any case failed.
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "core/scene/scene.h"

namespace fs = std::filesystem;

namespace {

struct Outcome {
  int status = -1;  // exit status; 128 + signal when killed
  std::string output;
};

std::string quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// Runs a shell command with a time limit; 124 (timeout's) marks a hang.
Outcome shell(const std::string& command, int seconds) {
  const std::string full =
      "timeout -s KILL " + std::to_string(seconds) + " sh -c " + quoted(command) + " 2>&1";
  Outcome o;
  FILE* pipe = ::popen(full.c_str(), "r");
  if (!pipe) return o;
  std::array<char, 4096> buffer;
  std::size_t n;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
    if (o.output.size() < (1u << 20)) o.output.append(buffer.data(), n);
  const int raw = ::pclose(pipe);
  o.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  if (o.status == 128 + 9) o.status = 124;  // timeout -s KILL
  return o;
}

std::string text_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// "nan" or "inf" as a value in a CSV or JSON output.
bool holds_non_finite(const fs::path& dir) {
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const auto ext = it->path().extension();
    if (ext != ".csv" && ext != ".json") continue;
    std::string t = text_of(it->path());
    for (auto& c : t) c = char(std::tolower(static_cast<unsigned char>(c)));
    for (const char* bad : {"nan", "inf"}) {
      for (auto p = t.find(bad); p != std::string::npos; p = t.find(bad, p + 1)) {
        // A word such as "infinite" or "finer" in a note is not a value: check the boundaries.
        const char before = p > 0 ? t[p - 1] : ',';
        const char after = p + 3 < t.size() ? t[p + 3] : ',';
        const auto sep = [](char c) {
          return c == ',' || c == '\n' || c == ' ' || c == '-' || c == '+' || c == ':' ||
                 c == '[' || c == ']';
        };
        if (sep(before) && (sep(after) || after == 'i')) return true;
      }
    }
  }
  return false;
}

struct Tally {
  int cases = 0, crashes = 0, hangs = 0, wrong_codes = 0, non_finite = 0, unnamed = 0;
  std::vector<std::string> failures;
  void fail(const std::string& what, const std::string& detail) {
    failures.push_back(what + ": " + detail);
  }
};

const std::vector<std::string> kHostile = {"nan",
                                           "inf",
                                           "-inf",
                                           "+inf",
                                           "1e308",
                                           "-1e308",
                                           "1e-308",
                                           "0",
                                           "-0",
                                           "-1",
                                           "1",
                                           "9223372036854775807",
                                           "-9223372036854775808",
                                           "99999999999999999999",
                                           "0.5",
                                           "2",
                                           "1e6",
                                           "\"\"",
                                           "\"x\"",
                                           "true",
                                           "false",
                                           "[]",
                                           "[nan]",
                                           "[1, 2",
                                           "[0, 100]",
                                           "[1e308]",
                                           "{}",
                                           "\"\\u0000\"",
                                           "\xff\xfe",
                                           "1e",
                                           "0x10",
                                           "1_000",
                                           "'a'",
                                           "= 3",
                                           "[[1]]",
                                           "\"off\""};

std::string mutate_value(std::mt19937_64& rng) {
  return kHostile[rng() % kHostile.size()];
}

// A scene file damaged the ways files are: cut short, a byte changed, a line repeated.
std::string mutate_text(std::string s, std::mt19937_64& rng) {
  if (s.empty()) return s;
  switch (rng() % 4) {
    case 0:
      s.resize(rng() % s.size());
      break;
    case 1:
      s[rng() % s.size()] = char(rng() % 256);
      break;
    case 2: {
      const auto at = rng() % s.size();
      const auto eol = s.find('\n', at);
      const auto bol = s.rfind('\n', at);
      const auto from = bol == std::string::npos ? 0 : bol + 1;
      s.insert(from, s.substr(from, eol == std::string::npos ? std::string::npos : eol - from + 1));
      break;
    }
    default: {
      // A number in the file replaced by a hostile value.
      const auto eq = s.find(" = ", rng() % s.size());
      if (eq == std::string::npos) return s;
      const auto eol = s.find('\n', eq);
      s.replace(eq + 3, (eol == std::string::npos ? s.size() : eol) - eq - 3, mutate_value(rng));
    }
  }
  return s;
}

// A short, small run of any scene: the fuzzed value decides, not the run's length.
const char* kShort =
    " --set run.end_time_s=1 --set output.frames=false --set output.particles=false"
    " --set output.fields=false --set instruments.hydrometer.times_min=[0.01]"
    " --set instruments.buoyancy.times_min=[0.01] --set instruments.pipette.times_min=[0.01]"
    " --quiet";

std::vector<std::string> keys;  // every scene key

void check_run(Tally& t, const std::string& what, const Outcome& o, const fs::path& out,
               const std::string& must_name) {
  ++t.cases;
  if (o.status == 124) {
    ++t.hangs;
    t.fail(what, "hang");
  } else if (o.status > 128) {
    ++t.crashes;
    t.fail(what, "crash, status " + std::to_string(o.status) + "\n" + o.output);
  } else if (o.status == 2) {
    // The key (or file) given, or another key the value clashes with, by name.
    bool named = must_name.empty() || o.output.find(must_name) != std::string::npos;
    for (const auto& k : keys) named = named || o.output.find(k + " = ") != std::string::npos;
    if (!named) {
      ++t.unnamed;
      t.fail(what, "exit 2 without naming " + must_name + ": " + o.output);
    }
  } else if (o.status == 0 || o.status == 5) {
    // 5: the engine refused to go on (an instability named with particle and time).
    if (o.status == 5 && o.output.find("instability") == std::string::npos &&
        o.output.find("memory") == std::string::npos) {
      ++t.wrong_codes;
      t.fail(what, "exit 5: " + o.output);
    }
    if (holds_non_finite(out)) {
      ++t.non_finite;
      t.fail(what, "NaN or inf in the outputs of " + out.string());
    }
  } else {
    ++t.wrong_codes;
    t.fail(what, "exit " + std::to_string(o.status) + ": " + o.output);
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App cli{"sedem fuzz: hostile scenes, --set values and reduce CSVs"};
  int cases = 40;
  std::uint64_t seed = 1;
  std::string sedem = SEDEM_EXE;
  std::string out_dir = "fuzz-out";
  int timeout = 60;
  cli.add_option("--cases", cases, "Cases of each kind (scene, --set, reduce)")
      ->capture_default_str();
  cli.add_option("--seed", seed, "Random seed")->capture_default_str();
  cli.add_option("--sedem", sedem, "The sedem executable")->capture_default_str();
  cli.add_option("--out", out_dir, "Scratch folder")->capture_default_str();
  cli.add_option("--timeout", timeout, "Seconds after which a case is a hang")
      ->capture_default_str();
  CLI11_PARSE(cli, argc, argv);

  std::mt19937_64 rng(seed);
  const fs::path scratch = fs::absolute(out_dir);
  fs::create_directories(scratch);
  std::vector<fs::path> scenes;
  for (const auto& e : fs::directory_iterator(fs::path(SEDEM_SOURCE_DIR) / "scenes"))
    if (e.path().extension() == ".toml") scenes.push_back(e.path());
  std::sort(scenes.begin(), scenes.end());
  sedem::Scene defaults;
  const sedem::Schema schema = defaults.schema();
  for (const auto& p : schema.params()) keys.push_back(p.key);
  Tally t;
  const fs::path run = scratch / "run";

  // 1. --set: a key of the schema, a hostile value.
  for (int i = 0; i < cases; ++i) {
    const std::string key = keys[rng() % keys.size()];
    const std::string value = mutate_value(rng);
    const fs::path& scene = scenes[rng() % scenes.size()];
    fs::remove_all(run);
    const auto o = shell(sedem + " run " + quoted(scene.string()) + " --out " + run.string() +
                             kShort + " --set " + quoted(key + "=" + value),
                         timeout);
    check_run(t, "--set " + key + "=" + value + " on " + scene.filename().string(), o, run, key);
  }
  // 2. A shipped scene file, damaged.
  for (int i = 0; i < cases; ++i) {
    const fs::path& scene = scenes[rng() % scenes.size()];
    const fs::path damaged = scratch / ("case_" + std::to_string(i) + ".toml");
    {
      std::ofstream out(damaged, std::ios::binary);
      out << mutate_text(text_of(scene), rng);
    }
    fs::remove_all(run);
    const auto o =
        shell(sedem + " run " + damaged.string() + " --out " + run.string() + kShort, timeout);
    check_run(t, "damaged " + scene.filename().string() + " (" + damaged.string() + ")", o, run,
              damaged.filename().string());
  }
  // 3. Laboratory CSVs for `sedem reduce`.
  const std::string lab =
      "time_min,reading_g_per_l,temperature_c,composite_correction_g_per_l\n"
      "2,42,22,5\n5,35,22,5\n15,28,22,5\n30,22,21.5,5\n60,18,21,5\n250,11,20,5\n1440,7,19,5\n";
  for (int i = 0; i < cases; ++i) {
    std::string csv = lab;
    const int edits = 1 + int(rng() % 3);
    for (int k = 0; k < edits; ++k) {
      if (rng() % 2) {
        csv = mutate_text(csv, rng);
      } else {
        // A cell replaced by a hostile value.
        auto comma = csv.find(',', rng() % csv.size());
        if (comma == std::string::npos) continue;
        auto next = csv.find_first_of(",\n", comma + 1);
        csv.replace(comma + 1, (next == std::string::npos ? csv.size() : next) - comma - 1,
                    mutate_value(rng));
      }
    }
    const fs::path file = scratch / ("lab_" + std::to_string(i) + ".csv");
    {
      std::ofstream out(file, std::ios::binary);
      out << csv;
    }
    const fs::path result = scratch / "reduced";
    fs::remove_all(result);
    fs::create_directories(result);
    const std::string mass = std::to_string(0.001 + double(rng() % 100000) / 100.0);
    const auto o = shell(sedem + " reduce " + file.string() + " --mass-g " + mass + " --out " +
                             (result / "points.csv").string(),
                         timeout);
    check_run(t, "reduce " + file.string() + " --mass-g " + mass, o, result, "");
  }

  std::printf(
      "sedem fuzz, seed %llu: %d cases; %d crashes, %d hangs, %d wrong exit codes, %d exit 2 "
      "without naming the key or file, %d with NaN/inf in the outputs\n",
      static_cast<unsigned long long>(seed), t.cases, t.crashes, t.hangs, t.wrong_codes, t.unnamed,
      t.non_finite);
  for (const auto& f : t.failures) std::printf("  FAILED %s\n", f.c_str());
  return t.failures.empty() ? 0 : 1;
}
