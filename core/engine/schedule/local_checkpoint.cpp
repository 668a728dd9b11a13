#include "core/engine/schedule/local_stepper.h"

#include <algorithm>
#include <cmath>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/engine/state/checkpoint_io.h"

namespace sedem {

void LocalStepper::save(std::ostream& out) const {
  write_vector(out, kind_);
  // The window records go field by field, as the checkpoint has always held them.
  write_field(out, track_, &Track::flight);
  write_field(out, track_, &Track::t0);
  write_field(out, track_, &Track::t1);
  write_field(out, track_, &Track::deposit_cell);
  write_vector(out, e_.voidage.solid());
  std::vector<Box> boxes(kind_.size());
  std::vector<std::uint8_t> kinds(kind_.size(), BoxRegistry::kNone);
  if (e_.model.contact)
    for (std::uint32_t id = 0; id < kind_.size(); ++id)
      if (boxes_.has(id)) {
        boxes[id] = boxes_.box(id);
        kinds[id] = boxes_.kind(id);
      }
  write_vector(out, boxes);
  write_vector(out, kinds);
  write_vector(out, land_y_);
  write_vector(out, bed_);
  std::vector<double> widened;  // id, sync time, the window's box (the old one is in boxes)
  for (const Ahead& a : widened_)
    widened.insert(widened.end(),
                   {double(a.id), a.time, a.after.x0, a.after.x1, a.after.y0, a.after.y1});
  write_vector(out, widened);
  if (own_steps_) {  // the lagging members: id, the time each is at
    std::vector<double> lags;
    for (std::uint32_t id : e_.state.origin)
      if (at_[id] >= 0) lags.insert(lags.end(), {double(id), at_[id]});
    write_vector(out, lags);
  }
}

void LocalStepper::load(std::istream& in) {
  read_vector(in, kind_);
  track_.assign(kind_.size(), Track{});
  read_field(in, track_, &Track::flight);
  read_field(in, track_, &Track::t0);
  read_field(in, track_, &Track::t1);
  read_field(in, track_, &Track::deposit_cell);
  std::vector<double> solid(e_.voidage.solid().size());
  read_vector(in, solid);
  e_.voidage.set_solid(solid);
  std::vector<Box> boxes(kind_.size());
  std::vector<std::uint8_t> kinds(kind_.size());
  read_vector(in, boxes);
  read_vector(in, kinds);
  read_vector(in, land_y_);
  read_vector(in, bed_);
  std::vector<double> widened;
  read_vector_upto(in, widened, 6 * std::uint64_t(kind_.size()));
  widened_.clear();
  for (std::size_t k = 0; k + 6 <= widened.size(); k += 6) {
    const double id = widened[k];
    if (!(id >= 0 && id < double(kind_.size())))
      throw std::runtime_error("damaged checkpoint: a widened box names no grain");
    widened_.push_back({std::uint32_t(id), widened[k + 1], Box{},
                        Box{widened[k + 2], widened[k + 3], widened[k + 4], widened[k + 5]}, true});
  }
  at_.assign(own_steps_ ? kind_.size() : 0, kInSync);
  lagging_ = 0;
  lag_cap_ = HUGE_VAL;
  own_.valid = false;
  own_.lagging_stale = true;
  if (own_steps_) {
    std::vector<double> lags;
    read_vector_upto(in, lags, 2 * std::uint64_t(kind_.size()));
    for (std::size_t k = 0; k + 2 <= lags.size(); k += 2) {
      const double id = lags[k], at = lags[k + 1];
      if (!(id >= 0 && id < double(kind_.size())) || !is_member(kind_[std::size_t(id)]) ||
          !(at >= 0 && std::isfinite(at)))
        throw std::runtime_error("damaged checkpoint: a lagging member's record is bad");
      at_[std::size_t(id)] = at;
      ++lagging_;
    }
  }
  if (land_y_.size() != kind_.size() || bed_.empty())
    throw std::runtime_error("damaged checkpoint: the coarse bed does not fit the sample");
  for (std::size_t id = 0; id < kind_.size(); ++id) {
    const FreeFlight& f = track_[id].flight;
    const bool finite =
        std::isfinite(f.x + f.y + f.vx + f.vy + f.rate + f.ux + f.uy + track_[id].t0) &&
        !std::isnan(track_[id].t1) && f.rate >= 0;
    if (box_tag(kind_[id]) > box_tag(GrainKind::retired) || !finite ||
        !std::isfinite(land_y_[id]) || track_[id].deposit_cell >= e_.voidage.cell_count() ||
        (kinds[id] != BoxRegistry::kNone && kinds[id] > box_tag(GrainKind::settled)))
      throw std::runtime_error("damaged checkpoint: grain " + std::to_string(id) +
                               " has a bad local-step state");
  }
  for (std::uint32_t id : e_.state.origin)
    if (id >= kind_.size() || !is_member(kind_[id]))
      throw std::runtime_error("damaged checkpoint: a member is not marked as one");
  if (e_.model.contact) {
    const Cylinder& cyl = e_.setup.cylinder;
    boxes_.configure(registry_cell_, cyl.half_width(), cyl.height, kind_.size());
    for (std::uint32_t id = 0; id < kind_.size(); ++id)
      if (kinds[id] != BoxRegistry::kNone) boxes_.set(id, boxes[id], kinds[id]);
  }
  // A coasting grain's lane is the column it was synced in, where its window starts.
  std::vector<std::vector<Sync>> due(lanes_.size());
  for (std::uint32_t id = 0; id < kind_.size(); ++id)
    if (kind_[id] == GrainKind::coasting)
      due[lane_of(track_[id].flight.x)].emplace_back(track_[id].t1, id);
  for (std::size_t l = 0; l < lanes_.size(); ++l) lanes_[l].syncs.assign(std::move(due[l]));
  member_.assign(kind_.size(), kNoMember);
  index_members();
  if (paced()) {
    e_.allowance.assign(e_.state.size(), HUGE_VAL);
    for (std::size_t k = 0; k < e_.state.size(); ++k) note_allowance(e_.state.origin[k], k);
  }
  settled_ = std::size_t(std::count(kind_.begin(), kind_.end(), GrainKind::settled));
  e_.forces.stiffness.assign(e_.state.size(), 0.0);
}

// The scheme's promise, checked grain by grain (for tests; O(n) queries): every grain is
// inside its box, no coasting grain's window has ended, and only grains that the common step
// handles (members, and settled grains beside frozen ones) hold overlapping boxes. One
// exception: a grain synced ahead of the members in a step a joining grain then shortened
// keeps its old box too, where a grain synced after it may have passed since (but no coasting
// grain's disc overlaps another's). Also: the members' copies of their tracks match the tracks,
// and a member's weight lies in the voidage cell it is in.
std::string LocalStepper::violation() const {
  if (own_steps_ && member_at_.size() != e_.state.size())
    return std::to_string(member_at_.size()) + " lagging times for " +
           std::to_string(e_.state.size()) + " members";
  if (member_track_.size() != e_.state.size())
    return std::to_string(member_track_.size()) + " copies of tracks for " +
           std::to_string(e_.state.size()) + " members";
  for (std::size_t k = 0; k < e_.state.size(); ++k) {
    const std::uint32_t id = e_.state.origin[k];
    const MemberTrack& m = member_track_[k];
    auto member = [&] {
      return "member " + std::to_string(k) + " (grain " + std::to_string(id) + ")";
    };
    if (m.x != track_[id].flight.x || m.y != track_[id].flight.y ||
        m.cell != track_[id].deposit_cell || (own_steps_ && member_at_[k] != at_[id]))
      return member() + ": its copy of its track differs from the track";
    if (e_.model.drag == DragLaw::di_felice &&
        m.cell != e_.voidage.cell(e_.state.x[k], e_.state.y[k]))
      return member() + ": its weight is in voidage cell " + std::to_string(m.cell) +
             ", not in the one it is in";
  }
  if (!e_.model.contact) return {};
  const Particles& s = e_.sample.particles;
  const std::size_t n = kind_.size();
  auto where = [&](std::uint32_t id) {
    if (kind_[id] == GrainKind::coasting) return coasting_at(id, e_.time);
    if (kind_[id] == GrainKind::settled)
      return FreeFlight::Point{track_[id].flight.x, track_[id].flight.y, 0, 0};
    if (kind_[id] == GrainKind::retired) return retired_at(id, e_.time);
    const std::size_t k = member_[id];
    return FreeFlight::Point{e_.state.x[k], e_.state.y[k], 0, 0};
  };
  auto name = [&](std::uint32_t id) {
    return "grain " + std::to_string(id) + " (" + name_of(kind_[id]) + ")";
  };
  for (std::uint32_t id = 0; id < n; ++id) {
    if (kind_[id] == GrainKind::coasting && track_[id].t1 < e_.time)
      return name(id) + ": its window ended at " + std::to_string(track_[id].t1) + " s, before " +
             std::to_string(e_.time) + " s";
    if (kind_[id] == GrainKind::retired) {
      if (boxes_.has(id)) return name(id) + " holds a box";
      continue;
    }
    if (!boxes_.has(id) && passes(id)) continue;  // a free grain that meets none
    const FreeFlight::Point p = where(id);
    const double r = 0.5 * s.diameter[id];
    const Box& b = boxes_.box(id);
    if (p.x - r < b.x0 || p.x + r > b.x1 || p.y - r < b.y0 || p.y + r > b.y1)
      return name(id) + " is outside its box";
  }
  for (std::uint32_t id = 0; id < n; ++id) {
    if (kind_[id] == GrainKind::retired) continue;
    std::string found;
    boxes_.overlapping(boxes_.box(id), id, [&](std::uint32_t j) {
      const GrainKind a = kind_[id], b = kind_[j];
      const bool ahead = (a == GrainKind::coasting && track_[id].t0 > e_.time) ||
                         (b == GrainKind::coasting && track_[j].t0 > e_.time);
      const bool passing = passes(id) && passes(j);
      const bool handled = ahead || passing ||
                           (a != GrainKind::coasting && b != GrainKind::coasting &&
                            !(a == GrainKind::settled && b == GrainKind::moving) &&
                            !(a == GrainKind::moving && b == GrainKind::settled));
      if (!handled && found.empty())
        found = "the boxes of " + name(id) + " and " + name(j) + " overlap";
      // Whatever their boxes, a coasting grain touches nothing it does not pass.
      if (found.empty() && !passing && (a == GrainKind::coasting || b == GrainKind::coasting)) {
        const FreeFlight::Point p = where(id), q = where(j);
        if (std::hypot(p.x - q.x, p.y - q.y) < 0.5 * (s.diameter[id] + s.diameter[j]))
          found = name(id) + " and " + name(j) + " overlap";
      }
    });
    if (!found.empty()) return found;
  }
  return {};
}

}  // namespace sedem
