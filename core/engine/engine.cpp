#include "core/engine/engine.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <vector>

#include "core/engine/integrate/simd_state.h"
#include "core/engine/schedule/engine_parts.h"
#include "core/engine/schedule/global_stepper.h"
#include "core/engine/schedule/local_stepper.h"
#include "core/engine/state/checkpoint_io.h"

namespace sedem {

namespace {
// The last byte is the format's version: 2 keeps the candidate lists' rows in the grid's order;
// 3 the stats of what set the step and of the carried sub-steps (EngineStats is written whole);
// 4 members' boxes with an allowance of 2 radii (a box of 3 read back as 2 would resume,
// safely, as neither version's run); 5 the candidate lists' widenings since their build; 6
// members' boxes of a few steps' travel (integrator.member_box_steps), which a version that
// read every member's box as 2 radii would let its grain leave.
constexpr char kMagic[8] = {'S', 'E', 'D', 'E', 'M', 'C', 'K', '6'};

// The particle state and the lists' build in checkpoint order, for saving and loading alike
// (`Parts`: EngineParts, const when saving).
template <class Parts, class Vector, class Value>
void checkpoint_fields(Parts& e, Vector&& vector, Value&& value) {
  for (auto* v : {&e.state.x, &e.state.y, &e.state.vx, &e.state.vy, &e.state.omega,
                  &e.state.diameter, &e.state.weight, &e.lists.search})
    vector(*v);
  vector(e.state.origin);
  vector(e.state.frozen);
  vector(e.lists.x0);
  vector(e.lists.y0);
  value(e.lists.stale);
  value(e.lists.grid_rows);
  value(e.resort.done_at);
}

}  // namespace

Engine::Engine(const EngineSetup& setup, Sample sample)
    : parts_(std::make_unique<EngineParts>(setup, std::move(sample))) {
  if (parts_->local)
    local_ = std::make_unique<LocalStepper>(*parts_);
  else
    global_ = std::make_unique<GlobalStepper>(*parts_);
}

Engine::~Engine() = default;

double Engine::time() const {
  return parts_->time;
}
const EngineStats& Engine::stats() const {
  return parts_->stats;
}
const char* Engine::integrator_name() const {
  return parts_->integrator->name();
}
int Engine::threads() const {
  return parts_->local ? std::max(parts_->sync_threads, parts_->threads) : parts_->threads;
}
double Engine::freeze_height() const {
  return parts_->freeze.height;
}
double Engine::retire_height() const {
  return local_ ? local_->retire_height() : 0.0;
}
std::string Engine::local_violation() const {
  return local_ ? local_->violation() : "";
}

const Particles& Engine::particles() const {
  EngineParts& e = *parts_;
  if (synced_step_ != e.stats.steps) {
    Particles& p = e.sample.particles;
    const EngineState& s = e.state;
    const std::size_t n = s.size();
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint32_t o = s.origin[i];
      p.x[o] = s.x[i];
      p.y[o] = s.y[i];
      p.vx[o] = s.vx[i];
      p.vy[o] = s.vy[i];
      p.omega[o] = s.omega[i];
    }
    if (local_) local_->write_free_grains(p);
    synced_step_ = e.stats.steps;
  }
  return e.sample.particles;
}

const Sample& Engine::sample() const {
  particles();
  return parts_->sample;
}

void Engine::advance_to(double t) {
  while (parts_->time < t) step(t);
}

void Engine::step(double limit) {
  clean_simd_state();
  if (local_)
    local_->step(limit);
  else
    global_->step(limit);
}

double Engine::kinetic_energy() const {
  const EngineParts& e = *parts_;
  double en = 0;
  if (local_) {
    const Particles& p = particles();
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double d = p.diameter[i], m = e.model.mass(d);
      en += 0.5 * m * (p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i]) +
            0.5 * 0.1 * m * d * d * p.omega[i] * p.omega[i];
    }
    return en;
  }
  const EngineState& s = e.state;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const double d = s.diameter[i], m = e.model.mass(d);
    en += 0.5 * m * (s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i]) +
          0.5 * 0.1 * m * d * d * s.omega[i] * s.omega[i];
  }
  return en;
}

std::size_t Engine::bytes() const {
  const EngineParts& e = *parts_;
  auto cap = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
  const Particles& p = e.sample.particles;
  const EngineState& s = e.state;
  const ForceAccumulators& f = e.forces;
  std::size_t b = cap(p.x) + cap(p.y) + cap(p.vx) + cap(p.vy) + cap(p.omega) + cap(p.diameter) +
                  cap(p.weight) + cap(p.size_class) + cap(p.id);
  b += cap(s.x) + cap(s.y) + cap(s.vx) + cap(s.vy) + cap(s.omega) + cap(s.diameter) +
       cap(s.weight) + cap(s.origin) + cap(s.frozen);
  b += cap(f.fx) + cap(f.fy) + cap(f.torque) + cap(f.stiffness) + cap(f.spin_stiffness) +
       cap(f.lubrication_stiffness);
  b += cap(e.lists.search) + cap(e.lists.x0) + cap(e.lists.y0) + e.resort.bytes();
  b += e.grid.bytes() + e.voidage.bytes() + e.pass.bytes() + e.lists.bytes() + e.springs.bytes() +
       e.next_springs.bytes();
  b += cap(e.allowance) + e.integrator->bytes();
  if (local_) b += local_->bytes();
  return b;
}

void Engine::save_checkpoint(const std::string& path) const {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error("cannot write checkpoint " + path);
  save_checkpoint(out);
  if (!out) throw std::runtime_error("failed writing checkpoint " + path);
}

void Engine::save_checkpoint(std::ostream& out) const {
  const EngineParts& e = *parts_;
  out.write(kMagic, sizeof kMagic);
  write_value(out, std::uint64_t(e.state.size()));
  write_value(out, e.time);
  write_value(out, e.stats);
  write_value(out, e.facts.contacts);
  write_value(out, e.facts.min_contact_mass);
  checkpoint_fields(
      e, [&](const auto& v) { write_vector(out, v); }, [&](const auto& v) { write_value(out, v); });
  write_vector(out, e.lists.widenings);
  const auto springs = e.springs.sorted_entries();
  const std::uint64_t count = springs.size();
  write_value(out, count);
  out.write(reinterpret_cast<const char*>(springs.data()),
            std::streamsize(count * sizeof(PairHistory::Entry)));
  e.integrator->save(out);
  if (local_) local_->save(out);
}

void Engine::load_checkpoint(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  load_checkpoint(in, path);
  if (in.peek() != std::char_traits<char>::eof())
    throw std::runtime_error("damaged checkpoint " + path + ": data after its end");
}

void Engine::load_checkpoint(std::istream& in, const std::string& path) {
  EngineParts& e = *parts_;
  char magic[sizeof kMagic];
  in.read(magic, sizeof magic);
  if (!in || std::memcmp(magic, kMagic, sizeof kMagic - 1) != 0)
    throw std::runtime_error("not a sedem checkpoint: " + path);
  if (magic[sizeof kMagic - 1] != kMagic[sizeof kMagic - 1])
    throw std::runtime_error(
        "checkpoint " + path + " was written by another version of sedem (format " +
        std::string(1, magic[sizeof kMagic - 1]) + ", this one reads " +
        std::string(1, kMagic[sizeof kMagic - 1]) + "): run it again from the start");
  std::uint64_t members = 0;
  read_value(in, members);
  if (e.local && in && members <= e.sample.particles.size()) {  // local steps: the members only
    e.state.resize(members);
    e.lists.search.resize(members);
    e.lists.x0.resize(members);
    e.lists.y0.resize(members);
  } else if (!e.local && members != e.sample.particles.size()) {
    throw std::runtime_error("checkpoint does not match this sample: " + path);
  }
  // What the file holds after the read position: a count read back is refused past it.
  auto bytes_left = [&]() -> std::uint64_t {
    const auto here = in.tellg();
    in.seekg(0, std::ios::end);
    const auto end = in.tellg();
    in.seekg(here);
    return here < 0 || end < here ? 0 : std::uint64_t(end - here);
  };
  // Every value read back is checked before it is used: a damaged file is refused with the
  // field it got wrong, never a crash or a silently shorter run.
  auto validate_loaded_state = [&](std::uint64_t springs) {
    auto bad = [&](const std::string& what) {
      throw std::runtime_error("damaged checkpoint " + path + ": " + what);
    };
    if (!in) bad("truncated");
    if (!std::isfinite(e.time) || e.time < 0 || e.time > e.setup.end_time * (1 + 1e-9))
      bad("time " + std::to_string(e.time) + " s is outside the run (0 to " +
          std::to_string(e.setup.end_time) + " s)");
    if (e.stats.steps < 0 || !std::isfinite(e.stats.particle_steps) || e.stats.particle_steps < 0)
      bad("negative step counts");
    // Sample indices: all of them, or with local steps those of the members.
    const std::size_t n = e.state.size(), ids = e.sample.particles.size();
    std::vector<std::uint8_t> seen(ids, 0);
    for (std::uint32_t o : e.state.origin) {
      if (o >= ids || seen[o]) bad("particle order entry " + std::to_string(o) + " is no particle");
      seen[o] = 1;
    }
    for (const auto* v :
         {&e.state.x, &e.state.y, &e.state.vx, &e.state.vy, &e.state.omega, &e.state.diameter,
          &e.state.weight, &e.lists.search, &e.lists.x0, &e.lists.y0})
      for (double x : *v)
        if (!std::isfinite(x)) bad("a particle's position, velocity or size is no number");
    for (std::size_t i = 0; i < n; ++i)
      if (!(e.state.diameter[i] > 0) || !(e.state.weight[i] >= 0) || e.state.frozen[i] > 1)
        bad("particle " + std::to_string(i) + " has a bad size, weight or frozen flag");
    if (e.resort.done_at < 0 || e.resort.done_at > e.stats.steps) bad("resort step out of range");
    if (!e.lists.widenings_fit(n))
      bad("a widening of the candidate lists names no particle or no wider radius");
    if (!e.lists.stale && e.lists.grid_rows > n)
      bad("the candidate lists' " + std::to_string(e.lists.grid_rows) + " rows exceed the " +
          std::to_string(n) + " particles the state holds");
    // The springs follow: no more of them than the file holds.
    if (springs > bytes_left() / sizeof(PairHistory::Entry))
      bad(std::to_string(springs) + " contacts announced, more than the file holds");
  };
  read_value(in, e.time);
  read_value(in, e.stats);
  e.facts = PassFacts{};
  read_value(in, e.facts.contacts);
  read_value(in, e.facts.min_contact_mass);
  checkpoint_fields(
      e, [&](auto& v) { read_vector(in, v); }, [&](auto& v) { read_value(in, v); });
  read_vector_upto(in, e.lists.widenings, bytes_left() / sizeof(CandidateLists::Widening));
  if (e.lists.stale) e.lists.widenings.clear();  // the next build starts afresh
  std::uint64_t count = 0;
  read_value(in, count);
  validate_loaded_state(count);
  std::vector<PairHistory::Entry> springs(count);
  in.read(reinterpret_cast<char*>(springs.data()),
          std::streamsize(count * sizeof(PairHistory::Entry)));
  e.springs.assign(&springs, 1);
  const std::uint64_t n = e.sample.particles.size();
  for (const auto& e : springs) {
    if (e.key == PairHistory::kEmpty) continue;
    const auto [a, b] = PairHistory::grains(e.key);
    if (a >= n || b >= n || !std::isfinite(e.spring))
      throw std::runtime_error("damaged checkpoint " + path + ": a contact names no particle");
  }
  e.integrator->load(in);
  if (local_) local_->load(in);
  if (!in) throw std::runtime_error("truncated checkpoint " + path);
  // The lists as they were: built from the saved build positions, in the saved order, and the
  // rows appended since.
  if (!e.lists.stale)
    e.lists.rebuild_at_build_positions(e.state, e.grid, e.local, e.lists.grid_rows);
  synced_step_ = -1;
}

}  // namespace sedem
