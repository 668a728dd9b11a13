// What looks at a run: the times observers want, merged; each snapshot shown to those that
// asked for it; a resumed run's replay shown only to those whose result depends on it.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/observe/observer_set.h"

namespace sedem {
namespace {

class Recorder : public Observer {
 public:
  Recorder(std::vector<double> times, bool accumulates)
      : times_(std::move(times)), accumulates_(accumulates) {}
  std::string name() const override { return "recorder"; }
  std::vector<double> wanted_times() const override { return times_; }
  void observe(double time, const Particles&) override { seen.push_back(time); }
  void finish() override { ++finished; }
  bool accumulates() const override { return accumulates_; }
  std::vector<double> seen;
  int finished = 0;

 private:
  std::vector<double> times_;
  bool accumulates_;
};

Snapshot at(double t) {
  Snapshot s;
  s.time = t;
  s.particles.resize(3);
  return s;
}

TEST(Every, EndsExactlyAtTheEnd) {
  EXPECT_EQ(every(10, 25), (std::vector<double>{0, 10, 20, 25}));
  EXPECT_EQ(every(10, 20), (std::vector<double>{0, 10, 20}));
}

TEST(MergeTimes, SortsAndMergesTimesCloserThanTheTolerance) {
  EXPECT_EQ(merge_times({{30, 10}, {10 + 1e-12, 20}, {}}), (std::vector<double>{10, 20, 30}));
  EXPECT_TRUE(contains_time({10, 20}, 20 * (1 + 1e-12)));
  EXPECT_FALSE(contains_time({10, 20}, 20.001));
}

TEST(ObserverSet, ShowsEachSnapshotOnlyToThoseWhoAskedForItsTime) {
  Recorder a({10, 30}, false), b({20, 30}, true);
  ObserverSet set;
  set.add(a);
  set.add(b);
  EXPECT_EQ(set.times(), (std::vector<double>{10, 20, 30}));
  for (double t : {10.0, 20.0, 25.0, 30.0}) set.show(at(t));
  EXPECT_EQ(a.seen, (std::vector<double>{10, 30}));
  EXPECT_EQ(b.seen, (std::vector<double>{20, 30}));
  Particles p;
  p.resize(2);
  set.show_in_place(10, p);  // the default in-place look makes the snapshot itself
  EXPECT_EQ(a.seen.back(), 10);
  set.finish();
  EXPECT_EQ(a.finished + b.finished, 2);
}

TEST(ObserverSet, ReplaysSavedSnapshotsOnlyToObserversThatAccumulate) {
  Recorder writer({10, 20, 30}, false), readings({20, 40}, true);
  ObserverSet set;
  set.add(writer);
  set.add(readings);
  EXPECT_FALSE(set.needs_replay(20));  // nothing accumulating wanted before 20 s
  EXPECT_TRUE(set.needs_replay(20.5));
  for (double t : {10.0, 20.0}) set.replay(at(t));
  EXPECT_TRUE(writer.seen.empty());  // its files are already written
  EXPECT_EQ(readings.seen, (std::vector<double>{20}));
}

}  // namespace
}  // namespace sedem
