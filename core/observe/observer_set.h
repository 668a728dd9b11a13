#pragma once

#include <vector>

#include "core/observe/observer.h"

namespace sedem {

// The observers of one run, none owned, in the order they came: the times they want, and
// each snapshot shown to those that asked for its time. A run feeds it from the engine; a
// resumed run and `sedem render` feed it saved snapshots again (replay).
class ObserverSet {
 public:
  void add(Observer& observer) { observers_.push_back(&observer); }

  // Every time some observer wants, ascending, close times merged.
  std::vector<double> times() const;
  void show(const Snapshot& snapshot) const;
  // The same without a copy of the particles (a run on one thread).
  void show_in_place(double time, const Particles& particles) const;

  // Whether an observer that accumulates wants a snapshot before `until`: a resumed run then
  // shows it the saved ones again, so that its readings are those of a run that never stopped.
  bool needs_replay(double until) const;
  // A saved snapshot, shown to the observers that accumulate (the others' files are there).
  void replay(const Snapshot& saved) const;
  void finish() const;

 private:
  std::vector<Observer*> observers_;
};

}  // namespace sedem
