#include "core/observe/observer_set.h"

namespace sedem {

std::vector<double> ObserverSet::times() const {
  std::vector<std::vector<double>> lists;
  for (const Observer* o : observers_) lists.push_back(o->wanted_times());
  return merge_times(lists);
}

void ObserverSet::show(const Snapshot& snapshot) const {
  for (Observer* o : observers_)
    if (contains_time(o->wanted_times(), snapshot.time))
      o->observe(snapshot.time, snapshot.particles);
}

void ObserverSet::show_in_place(double time, const Particles& particles) const {
  for (Observer* o : observers_)
    if (contains_time(o->wanted_times(), time)) o->observe(time, particles);
}

bool ObserverSet::needs_replay(double until) const {
  for (const Observer* o : observers_)
    if (o->accumulates())
      for (double t : o->wanted_times())
        if (t < until) return true;
  return false;
}

void ObserverSet::replay(const Snapshot& saved) const {
  for (Observer* o : observers_)
    if (o->accumulates() && contains_time(o->wanted_times(), saved.time))
      o->observe(saved.time, saved.particles);
}

void ObserverSet::finish() const {
  for (Observer* o : observers_) o->finish();
}

}  // namespace sedem
