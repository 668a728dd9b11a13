#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "app/progress.h"

namespace sedem::app {
namespace {

// Everything a Progress prints, read back.
std::string printed(std::FILE* f) {
  std::string text;
  std::rewind(f);
  for (int c; (c = std::fgetc(f)) != EOF;) text += char(c);
  return text;
}

// A long inversion says how far it is; a quick one prints nothing.
TEST(StageProgress, PrintsOnlyOnceItHasRunAFewSeconds) {
  std::FILE* f = std::tmpfile();
  StageProgress log("invert", false, f, false, 2.0, 10.0);
  log.update_at(0.5, "fit", 0.0);
  log.update_at(1.9, "fit", 0.5);
  EXPECT_EQ(printed(f), "");
  std::fseek(f, 0, SEEK_END);
  log.update_at(2.5, "fit", 0.75);
  log.update_at(3.0, "fit", 0.8);     // within the log's interval: nothing
  log.update_at(3.5, "band", 0.0);    // a new stage: a line
  log.update_at(14.0, "band", 0.42);  // the interval passed: a line
  log.done();
  EXPECT_EQ(printed(f),
            "sedem: invert: fit 75% (wall 0:03)\n"
            "sedem: invert: band 0% (wall 0:04)\n"
            "sedem: invert: band 42% (wall 0:14)\n");
  std::fclose(f);
  // Quiet: nothing, however long.
  std::FILE* g = std::tmpfile();
  StageProgress quiet("invert", true, g, false);
  quiet.update_at(100, "band", 0.5);
  EXPECT_EQ(printed(g), "");
  std::fclose(g);
}

TEST(Progress, ATerminalLineStaysWithinEightyColumns) {
  // The 24 h test: long simulated and wall times, every stage of the run.
  Progress p(86400, false, nullptr, true, 80);
  const double walls[] = {0.5, 59, 3599, 3600 * 11.5, 3600 * 99};
  const double times[] = {0.0, 12.5, 4321.75, 86000, 86400};
  for (int i = 0; i < 5; ++i) {
    const std::string line = p.line(walls[i], times[i], 1.23456e9 * (i + 1));
    EXPECT_LE(line.size(), 79u) << line;
    EXPECT_EQ(line.front(), '[') << line;  // a bar
    EXPECT_NE(line.find("ETA"), std::string::npos) << line;
  }
  // A narrow terminal gets a narrower line.
  Progress narrow(86400, false, nullptr, true, 50);
  EXPECT_LE(narrow.line(10, 100, 1e6).size(), 49u);
}

TEST(Progress, TheEtaFollowsTheRecentRate) {
  // Slow at first (the grains accelerate under short steps), fast later: 100 s of wall for
  // the first 1 % of 86 400 s, then 1 % every second.
  Progress p(86400, false, nullptr, false, 80);
  p.line(0, 0, 0);
  p.line(100, 864, 0);
  double t = 864;
  for (int s = 101; s <= 160; ++s) p.line(s, t += 864, 0);
  // 61 % done, 1 % a second: about 39 s left, not the average's 100 s.
  const double eta = p.eta(160, t);
  EXPECT_NEAR(eta, 39, 3);
}

TEST(Progress, OffATerminalPlainLinesAtIntervals) {
  std::FILE* f = std::tmpfile();
  Progress p(120, false, f, false, 80, 0.0);
  p.update(10, 1e6);
  p.update(20, 2e6);
  p.done();
  const std::string text = printed(f);
  std::fclose(f);
  EXPECT_EQ(text.find('\r'), std::string::npos) << text;
  EXPECT_NE(text.find("t = 10.0 of 120.0 s"), std::string::npos) << text;
  EXPECT_NE(text.find("t = 20.0 of 120.0 s"), std::string::npos) << text;
  // The ETA is known from the second line on.
  EXPECT_EQ(text.find("ETA --:--", text.find("t = 20.0")), std::string::npos) << text;
}

TEST(Progress, OnATerminalOneLineRedrawnInPlace) {
  std::FILE* f = std::tmpfile();
  Progress p(120, false, f, true, 80);
  p.update(10, 1e6);  // within 0.2 s of the start: not drawn yet
  p.done();
  EXPECT_EQ(printed(f), "");
  std::fclose(f);
}

TEST(Progress, TheSummaryShowsEachTestAndWhereTheFiguresAre) {
  const nlohmann::json results = {
      {"hydrometer", {{"error_pp", 1.234}, {"bias_pp", 5.678}, {"readings", 3}}},
      {"buoyancy", {{"error_pp", nullptr}, {"bias_pp", nullptr}, {"readings", 2}}},
      {"pipette", {{"error_pp", nullptr}, {"bias_pp", nullptr}, {"readings", 0}}}};
  const std::string text = run_summary(results, 65.4, "no/such/run");
  EXPECT_NE(text.find("done in 65.4 s (1:05 wall)"), std::string::npos) << text;
  EXPECT_NE(text.find("hydrometer           1.23         5.68         3"), std::string::npos)
      << text;
  EXPECT_NE(text.find("pipette                 -            -         0"), std::string::npos)
      << text;
  // A reading that is no number: the figure is absent, not 0.
  EXPECT_NE(text.find("buoyancy                -            -         2"), std::string::npos)
      << text;
  std::size_t start = 0;
  for (std::size_t end; (end = text.find('\n', start)) != std::string::npos; start = end + 1)
    EXPECT_LE(end - start, 80u) << text.substr(start, end - start);
}

}  // namespace
}  // namespace sedem::app
