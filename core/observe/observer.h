#pragma once

#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "core/model/snapshot.h"

namespace sedem {

// Something that looks at the simulation and cannot change it (fields, instruments, writers,
// renderers). It says at which simulated times it needs the particles; the run stops the
// engine at the union of those times and hands each observer the snapshots it asked for,
// in time order, on one thread (the main thread: VTK and GL live there).
class Observer {
 public:
  virtual ~Observer() = default;
  virtual std::string name() const = 0;
  // Times (s) at which this observer wants a snapshot, ascending.
  virtual std::vector<double> wanted_times() const = 0;
  // The particles at that time, where they are (a snapshot's, or the engine's own in a run
  // without snapshots): an observer that keeps them copies what it keeps. (A default that
  // made a Snapshot for observers that only read had each of them copy 64 bytes a particle
  // at every output of a run without snapshots.)
  virtual void observe(double time, const Particles& particles) = 0;
  // After the last snapshot, or when the run is stopped early: flush what was computed.
  virtual void finish() {}
  // True for an observer whose result depends on every snapshot it has seen (readings,
  // profiles): a resumed run shows it the saved snapshots again before going on. A writer
  // of per-snapshot files returns false: its files are already there.
  virtual bool accumulates() const { return false; }
  // An observer that accumulates little (readings, profiles) keeps it in the run's checkpoint
  // instead: a resumed run restores it and shows it no saved snapshot again. (The snapshots a
  // replay needs were written at every reading, compressed: at a million particles a fifth of
  // a run's time, at ten million gigabytes.) load_state throws std::runtime_error naming what
  // it found damaged.
  virtual bool keeps_state() const { return false; }
  virtual void save_state(std::ostream&) const {}
  virtual void load_state(std::istream&) {}
};

// Output times every `interval` from 0 to `end` inclusive (the last one at `end` exactly).
std::vector<double> every(double interval, double end);

// The sorted union of several time lists, with times closer than `tolerance` merged.
std::vector<double> merge_times(const std::vector<std::vector<double>>& lists,
                                double tolerance = 1e-9);

// Does `times` contain `t` (within tolerance)?
bool contains_time(const std::vector<double>& times, double t, double tolerance = 1e-9);

}  // namespace sedem
