#include "core/observe/observer_set.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <istream>
#include <map>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace sedem {

std::vector<double> ObserverSet::times() const {
  std::vector<std::vector<double>> lists;
  for (const Observer* o : observers_) lists.push_back(o->wanted_times());
  return merge_times(lists);
}

void ObserverSet::add(Observer& observer) {
  observers_.push_back(&observer);
  shown_until_.push_back(-HUGE_VAL);
}

void ObserverSet::show_in_place(double time, const Particles& particles) const {
  for (std::size_t k = 0; k < observers_.size(); ++k) {
    Observer* o = observers_[k];
    if (!contains_time(o->wanted_times(), time)) continue;
    // A restored state holds the time the run stopped at: a resumed run shows it again.
    if (o->keeps_state() && time <= shown_until_[k] + 1e-9 * std::max(1.0, std::abs(time)))
      continue;
    o->observe(time, particles);
    shown_until_[k] = time;
  }
}

void ObserverSet::show(const Snapshot& snapshot) const {
  show_in_place(snapshot.time, snapshot.particles);
}

bool ObserverSet::needs_replay(double until) const {
  for (const Observer* o : observers_)
    if (o->accumulates() && !o->keeps_state())
      for (double t : o->wanted_times())
        if (t < until) return true;
  return false;
}

void ObserverSet::replay(const Snapshot& saved) const {
  for (Observer* o : observers_)
    if (o->accumulates() && !o->keeps_state() && contains_time(o->wanted_times(), saved.time))
      o->observe(saved.time, saved.particles);
}

namespace {

constexpr char kStateMagic[8] = {'S', 'E', 'D', 'E', 'M', 'O', 'B', 'S'};
// Bounds that no honest state reaches: a damaged length is refused before it is allocated.
constexpr std::uint64_t kMostSections = 1024, kLongestName = 256;

void write_u64(std::ostream& out, std::uint64_t v) {
  out.write(reinterpret_cast<const char*>(&v), sizeof v);
}

std::uint64_t read_u64(std::istream& in, const char* what) {
  std::uint64_t v = 0;
  in.read(reinterpret_cast<char*>(&v), sizeof v);
  if (!in)
    throw std::runtime_error(std::string("the observers' state is truncated (") + what + ")");
  return v;
}

}  // namespace

void ObserverSet::save_state(std::ostream& out) const {
  std::uint64_t count = 0;
  for (const Observer* o : observers_) count += o->keeps_state();
  out.write(kStateMagic, sizeof kStateMagic);
  write_u64(out, count);
  for (std::size_t k = 0; k < observers_.size(); ++k) {
    const Observer* o = observers_[k];
    if (!o->keeps_state()) continue;
    std::ostringstream section;
    section.write(reinterpret_cast<const char*>(&shown_until_[k]), sizeof(double));
    o->save_state(section);
    const std::string name = o->name(), bytes = section.str();
    write_u64(out, name.size());
    out.write(name.data(), std::streamsize(name.size()));
    write_u64(out, bytes.size());
    out.write(bytes.data(), std::streamsize(bytes.size()));
  }
}

void ObserverSet::load_state(std::istream& in) const {
  char magic[sizeof kStateMagic];
  in.read(magic, sizeof magic);
  if (!in || !std::equal(magic, magic + sizeof magic, kStateMagic))
    throw std::runtime_error("the observers' state is missing");
  const std::uint64_t count = read_u64(in, "count");
  if (count > kMostSections)
    throw std::runtime_error("the observers' state is damaged (" + std::to_string(count) +
                             " sections)");
  std::map<std::string, std::string> sections;
  for (std::uint64_t k = 0; k < count; ++k) {
    const std::uint64_t length = read_u64(in, "a name's length");
    if (length > kLongestName)
      throw std::runtime_error("the observers' state is damaged (a name of " +
                               std::to_string(length) + " bytes)");
    std::string name(length, '\0');
    in.read(name.data(), std::streamsize(length));
    const std::uint64_t size = read_u64(in, "a section's length");
    // Read in pieces: a damaged length ends at the file's end, not in a huge allocation.
    std::string bytes;
    char buffer[1 << 16];
    for (std::uint64_t left = size; left > 0 && in;) {
      const std::uint64_t piece = std::min<std::uint64_t>(left, sizeof buffer);
      in.read(buffer, std::streamsize(piece));
      bytes.append(buffer, std::size_t(in.gcount()));
      left -= std::uint64_t(in.gcount());
      if (in.gcount() == 0) break;
    }
    if (!in || bytes.size() != size)
      throw std::runtime_error("the observers' state is truncated (" + name + ")");
    sections[name] = std::move(bytes);
  }
  for (std::size_t k = 0; k < observers_.size(); ++k) {
    Observer* o = observers_[k];
    if (!o->keeps_state()) continue;
    const auto it = sections.find(o->name());
    if (it == sections.end())
      throw std::runtime_error("the checkpoint holds no state of the " + o->name());
    std::istringstream section(it->second);
    try {
      double shown = 0;
      section.read(reinterpret_cast<char*>(&shown), sizeof shown);
      if (!section || std::isnan(shown)) throw std::runtime_error("no last time");
      shown_until_[k] = shown;
      o->load_state(section);
    } catch (const std::exception& e) {
      throw std::runtime_error("the saved state of the " + o->name() + " is damaged: " + e.what());
    }
    if (section.peek() != std::char_traits<char>::eof())
      throw std::runtime_error("the saved state of the " + o->name() +
                               " is damaged: data after its end");
  }
}

void ObserverSet::finish() const {
  for (Observer* o : observers_) o->finish();
}

}  // namespace sedem
