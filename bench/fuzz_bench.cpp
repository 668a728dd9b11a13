// Hostile input against `sedem`: seeded mutations of the shipped scenes, of --set values, of
// laboratory CSVs for `sedem reduce` and `sedem invert` and sieve analyses (random rows, NaN, inf,
// huge and tiny values, CR/LF mixes, empty and header-only files), of a run folder for `sedem
// render` (a .vtp, particles.pvd or run.json cut short or changed), of a checkpoint for `sedem
// run --resume` and of a batch's plan (batch.json: cut short, keys of the wrong type, missing,
// huge numbers, folders outside the batch's) for `sedem batch --gather`. Every case must end in
// exit 2 naming what is wrong, or in a run (or reduction, inversion, redrawing, summary) whose
// outputs hold no NaN or inf; never a crash, a hang or another exit code. The test suite runs a few
// cases of each kind (seconds); run it longer with
//   build/bench/sedem_bench_fuzz --cases 2000 --seed 7
// Prints the counts and exits 1 if any case failed.
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

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

// A laboratory CSV damaged: a text mutation, a cell made hostile, random rows, its line ends
// changed or mixed, emptied, or cut to its header.
std::string mutate_lab(std::string csv, std::mt19937_64& rng) {
  const auto header_end = csv.find('\n');
  switch (rng() % 7) {
    case 0:
      return mutate_text(csv, rng);
    case 1: {
      auto comma = csv.find(',', header_end + rng() % (csv.size() - header_end));
      if (comma == std::string::npos) return csv;
      auto next = csv.find_first_of(",\n", comma + 1);
      csv.replace(comma + 1, (next == std::string::npos ? csv.size() : next) - comma - 1,
                  mutate_value(rng));
      return csv;
    }
    case 2: {
      // Random rows: numbers of any size, hostile values, as many as a cap allows and more.
      const int rows = int(rng() % 4 == 0 ? 150 + rng() % 300 : 1 + rng() % 6);
      const auto columns = std::count(csv.begin(), csv.begin() + long(header_end), ',') + 1;
      for (int r = 0; r < rows; ++r) {
        for (long c = 0; c < columns; ++c) {
          if (c) csv += ',';
          if (rng() % 5 == 0)
            csv += mutate_value(rng);
          else
            csv += std::to_string(std::ldexp(double(rng() % 1000), int(rng() % 80) - 40));
        }
        csv += '\n';
      }
      return csv;
    }
    case 3: {
      // Line ends: CRLF, CR alone, or each line its own.
      std::string out;
      const int mode = int(rng() % 3);
      for (char c : csv) {
        if (c != '\n') {
          out += c;
          continue;
        }
        const int end = mode == 2 ? int(rng() % 3) : mode;
        out += end == 0 ? "\r\n" : end == 1 ? "\r" : "\n";
      }
      return out;
    }
    case 4:
      return "";
    case 5:
      return csv.substr(0, header_end + 1);
    default:
      return csv.substr(0, header_end);  // the header alone, no line end
  }
}

// A fresh copy of the folder `from` at `to`, to damage.
fs::path fresh_copy(const fs::path& from, const fs::path& to) {
  fs::remove_all(to);
  fs::copy(from, to, fs::copy_options::recursive);
  return to;
}

// A file damaged the ways files are: cut short (anywhere, or its last bytes), bytes changed,
// emptied, or its text mutated.
void damage_file(const fs::path& file, std::mt19937_64& rng) {
  std::string bytes = text_of(file);
  switch (rng() % 5) {
    case 0:
      bytes.resize(bytes.empty() ? 0 : rng() % bytes.size());
      break;
    case 1:
      bytes.resize(bytes.size() > 40 ? bytes.size() - 1 - rng() % 40 : 0);
      break;
    case 2:
      for (int k = 0; k < 1 + int(rng() % 8) && !bytes.empty(); ++k)
        bytes[rng() % bytes.size()] = char(rng() % 256);
      break;
    case 3:
      bytes.clear();
      break;
    default:
      bytes = mutate_text(bytes, rng);
  }
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out << bytes;
}

// A batch's plan (batch.json) damaged: one key of the plan or of a run made hostile (a value of
// another type, a huge number, a folder outside the batch's) or removed. `key` receives the key as
// the reader names it ("seeds", "runs[1].seed").
std::string mutate_plan(const std::string& text, std::mt19937_64& rng, std::string& key) {
  key.clear();
  auto plan = nlohmann::json::parse(text);
  auto& runs = plan["runs"];
  const std::size_t run = rng() % runs.size();
  const bool top = rng() % 3 == 0;
  auto& object = top ? plan : runs[run];
  std::vector<std::string> keys;
  for (const auto& item : object.items()) keys.push_back(item.key());
  const std::string name = keys[rng() % keys.size()];
  key = top ? name : "runs[" + std::to_string(run) + "]." + name;
  if (rng() % 4 == 0) {
    object.erase(name);
    return plan.dump(2);
  }
  // Put a marker in and replace it by the hostile text: not every hostile value is JSON.
  static const std::vector<std::string> kOutside = {
      "\"..\"",     "\".\"",          "\"\"",
      "\"/tmp\"",   "\"../outside\"", "\"a/b\"",
      "\"a\\\\b\"", "\"\\n\"",        "18446744073709551615",
      "1e400",      "2147483648",     "-9223372036854775809"};
  const std::string value = rng() % 3 == 0 ? kOutside[rng() % kOutside.size()] : mutate_value(rng);
  object[name] = "@@hostile@@";
  std::string out = plan.dump(2);
  const std::string marker = "\"@@hostile@@\"";
  out.replace(out.find(marker), marker.size(), value);
  return out;
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
  cli.add_option("--cases", cases,
                 "Cases of each kind (--set, scene, reduce, invert, render, resume, gather)")
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

  // 3b. A sieve analysis for `sedem reduce --sieve`, damaged, beside the readings in the
  // lab's words with ';' and decimal commas, as a spreadsheet in a comma locale saves them.
  const std::string sieves =
      "opening (mm),mass retained (g)\n9.5,0\n4.75,12\n2,18\n0.425,30\n0.075,40\npan,100\n"
      "total,200\n";
  const fs::path semicolons = scratch / "lab_semicolons.csv";
  {
    std::ofstream out(semicolons, std::ios::binary);
    out << "time (min);R (g/L);T (\xC2\xB0"
           "C);C (g/L)\n2;42;22,0;5\n5;35;22;5\n15;28;22;5\n60;18;21,5;5\n1440;7;19;5\n";
  }
  for (int i = 0; i < cases; ++i) {
    const fs::path file = scratch / ("sieve_" + std::to_string(i) + ".csv");
    {
      std::ofstream out(file, std::ios::binary);
      out << mutate_lab(sieves, rng);
    }
    const fs::path result = scratch / "whole";
    fs::remove_all(result);
    fs::create_directories(result);
    const auto o = shell(sedem + " reduce " + semicolons.string() + " --sieve " + file.string() +
                             " --out " + (result / "whole.csv").string() + " --report " +
                             (result / "report.html").string(),
                         timeout);
    check_run(t, "reduce --sieve " + file.string(), o, result, "");
  }

  // 4. Laboratory CSVs for `sedem invert`, each test's form.
  const std::vector<std::pair<std::string, std::string>> invert_bases = {
      {"hydrometer", lab},
      {"buoyancy",
       "time_min,apparent_mass_g\n0.5,1.20\n1,1.12\n2,1.05\n5,0.97\n15,0.90\n60,0.86\n"},
      {"pipette", "time_min,dry_mass_g\n0.5,0.40\n1,0.35\n2,0.30\n5,0.22\n15,0.15\n60,0.08\n"}};
  for (int i = 0; i < cases; ++i) {
    const auto& [test, base] = invert_bases[rng() % invert_bases.size()];
    const std::string csv = mutate_lab(base, rng);
    const fs::path file = scratch / ("invert_" + std::to_string(i) + ".csv");
    {
      std::ofstream out(file, std::ios::binary);
      out << csv;
    }
    const fs::path result = scratch / "inverted";
    fs::remove_all(result);
    const auto o = shell(sedem + " invert " + file.string() + " --test " + test +
                             " --replicas 10 --quiet --out " + result.string(),
                         timeout);
    check_run(t, "invert " + file.string() + " --test " + test, o, result, "");
  }
  // 5. A run folder for `sedem render`, damaged: a .vtp, particles.pvd or run.json.
  const fs::path good = scratch / "good_run";
  fs::remove_all(good);
  const auto made = shell(
      sedem + " run " + (fs::path(SEDEM_SOURCE_DIR) / "scenes/demo.toml").string() + " --out " +
          good.string() + " --quiet --set run.end_time_s=2 --set output.frames=false",
      timeout);
  if (made.status != 0) {
    std::printf("sedem fuzz: the run to damage failed: %s\n", made.output.c_str());
    return 1;
  }
  for (int i = 0; i < cases; ++i) {
    const fs::path dir = fresh_copy(good, scratch / "damaged_run");
    std::vector<fs::path> files = {dir / "particles.pvd", dir / "run.json"};
    for (const auto& e : fs::directory_iterator(dir / "particles")) files.push_back(e.path());
    std::sort(files.begin() + 2, files.end());
    const fs::path& victim = files[rng() % files.size()];
    damage_file(victim, rng);
    const auto o = shell(sedem + " render --quiet " + dir.string(), timeout);
    check_run(t, "render of a folder with " + victim.filename().string() + " damaged", o, dir, "");
  }
  // 6. A checkpoint for `sedem run --resume`, damaged: checkpoint.bin or checkpoint.json.
  const fs::path stopped = scratch / "stopped_run";
  fs::remove_all(stopped);
  const auto killed =
      shell(sedem + " run " + (fs::path(SEDEM_SOURCE_DIR) / "scenes/demo.toml").string() +
                " --out " + stopped.string() +
                " --quiet --set run.end_time_s=6 --set output.frames=false"
                " --set integrator.crossing_fraction=0.1 --set integrator.max_coast_s=0.002"
                " --set run.checkpoint_interval_s=0.2 & pid=$!; for i in $(seq 400); do [ -f " +
                stopped.string() +
                "/checkpoint.json ] && break; sleep 0.05; done; kill -KILL $pid; wait $pid",
            timeout);
  if (!fs::exists(stopped / "checkpoint.bin")) {
    std::printf("sedem fuzz: the run to stop left no checkpoint: %s\n", killed.output.c_str());
    return 1;
  }
  for (int i = 0; i < cases; ++i) {
    const fs::path dir = fresh_copy(stopped, scratch / "damaged_checkpoint");
    const fs::path victim = dir / (rng() % 2 ? "checkpoint.bin" : "checkpoint.json");
    damage_file(victim, rng);
    const auto o = shell(sedem + " run --resume " + dir.string() + " --quiet", timeout);
    check_run(t, "run --resume with " + victim.filename().string() + " damaged", o, dir, "");
  }

  // 7. A batch's plan for `sedem batch --gather`, damaged; the batch's runs are complete, so
  // an exit 2 is the plan's fault and names it (and the key, when the plan still parses), or
  // the runs a damaged plan names instead are missing. The tasks themselves read their own
  // scene (tasks/RUN.toml), not the plan.
  const fs::path batch = scratch / "batch";
  fs::remove_all(batch);
  const auto emitted =
      shell(sedem + " batch " + (fs::path(SEDEM_SOURCE_DIR) / "scenes/demo.toml").string() +
                " --seeds 2 --emit parallel --out " + batch.string() + kShort + " && " +
                (batch / "tasks/run_task.sh").string() + " demo__seed=1 && " +
                (batch / "tasks/run_task.sh").string() + " demo__seed=2 && " + sedem +
                " batch --gather " + batch.string() + " --quiet",
            timeout);
  if (emitted.status != 0) {
    std::printf("sedem fuzz: the batch to damage failed: %s\n", emitted.output.c_str());
    return 1;
  }
  const std::string plan_text = text_of(batch / "batch.json");
  for (int i = 0; i < cases; ++i) {
    std::string key;
    {
      const std::string damaged = mutate_plan(plan_text, rng, key);
      std::ofstream out(batch / "batch.json", std::ios::binary | std::ios::trunc);
      out << damaged;
    }
    // And its text, maybe: then any key may be the one named, or none if it no longer parses.
    const bool text_damaged = rng() % 3 == 0;
    if (text_damaged) damage_file(batch / "batch.json", rng);
    const fs::path kept = scratch / ("batch_" + std::to_string(i) + ".json");
    fs::copy_file(batch / "batch.json", kept, fs::copy_options::overwrite_existing);
    const auto o = shell(sedem + " batch --gather " + batch.string() + " --quiet", timeout);
    const std::string what = "batch --gather with batch.json damaged (" + kept.string() + ")";
    check_run(t, what, o, batch, "");
    const auto says = [&](const std::string& s) { return o.output.find(s) != std::string::npos; };
    if (o.status == 2 && !says("did not complete") &&
        !(says("batch.json: ") &&
          (text_damaged || says(key) || says("not a batch plan") || says("format version")))) {
      ++t.unnamed;
      t.fail(what, "exit 2 without naming batch.json and " + key + ": " + o.output);
    }
  }

  std::printf(
      "sedem fuzz, seed %llu: %d cases; %d crashes, %d hangs, %d wrong exit codes, %d exit 2 "
      "without naming the key or file, %d with NaN/inf in the outputs\n",
      static_cast<unsigned long long>(seed), t.cases, t.crashes, t.hangs, t.wrong_codes, t.unnamed,
      t.non_finite);
  for (const auto& f : t.failures) std::printf("  FAILED %s\n", f.c_str());
  return t.failures.empty() ? 0 : 1;
}
