#pragma once

#include <iosfwd>
#include <vector>

#include "core/observe/observer.h"

namespace sedem {

// The observers of one run, none owned, in the order they came: the times they want, and
// each snapshot shown to those that asked for its time. A run feeds it from the engine; a
// resumed run and `sedem render` feed it saved snapshots again (replay).
class ObserverSet {
 public:
  void add(Observer& observer);

  // Every time some observer wants, ascending, close times merged.
  std::vector<double> times() const;
  // An observer that keeps a state is shown no time it has seen (a restored one, the time
  // its run stopped at).
  void show(const Snapshot& snapshot) const;
  // The same without a copy of the particles (a run on one thread).
  void show_in_place(double time, const Particles& particles) const;

  // Whether an observer that accumulates and keeps no state wants a snapshot before `until`:
  // a resumed run then shows it the saved ones again, so that its readings are those of a run
  // that never stopped.
  bool needs_replay(double until) const;
  // A saved snapshot, shown to the observers that accumulate and keep no state (the others'
  // files are there, or their state is restored).
  void replay(const Snapshot& saved) const;
  // The states of the observers that keep one (Observer::keeps_state), after the engine's in
  // a checkpoint: each under its name, with its length.
  void save_state(std::ostream& out) const;
  // Restores them from what save_state wrote. Throws std::runtime_error naming the observer
  // whose state is missing or damaged. Sections of observers not watched are skipped.
  void load_state(std::istream& in) const;
  void finish() const;

 private:
  std::vector<Observer*> observers_;
  // Per observer: the last time it was shown (a constant set is still shown snapshots; its
  // observers change, not the set).
  mutable std::vector<double> shown_until_;
};

}  // namespace sedem
