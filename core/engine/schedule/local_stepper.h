#pragma once

// Local time stepping of the exponential integrator (integrator.local_steps).
//
// A grain that touches nothing moves on an exact trajectory (free_flight.h): weight, buoyancy
// and a drag held constant. The common step exists only so that no grain passes through
// another between two looks. So a grain that provably cannot reach any other grain, wall or
// the bed for a while need not share it: it *coasts* over a window of its own, evaluated
// exactly at any time inside it, and is looked at again only at the window's end (its
// *sync*), where its drag and the voidage it feels are taken anew.
//
// Proof that nothing is missed: every grain holds a box in a BoxRegistry that it cannot leave
// before it is looked at again — a coasting grain the box its trajectory sweeps over its
// window, a member of the common step its position with an allowance of kAllowance pace radii
// (re-anchored once it has used kReanchor of them; it moves at most crossing_fraction < 1 of one
// a step), a settled grain its disc — each widened by a skin (kSkin radii, a coasting grain's
// kCoastSkin). A member's pace radius is its own, or, with carried steps, that of a coarser
// grain it is held against, or, for a coarse grain at a high count, a few steps' travel
// (integrator.member_box_steps). A window is chosen so that its box overlaps no other box and
// no wall; the longest such window up to integrator.max_coast_s, halved until it fits and then
// bisected between the clear length and the blocked one. A grain that
// cannot coast even over its own crossing time joins the common step (it is *engaged*), and
// whatever its box then overlaps joins with it: coasting grains at their exact position now,
// settled ones as frozen members. Members that touch nothing leave again as soon as a window fits
// (checked every kReleaseEvery steps), a group that holds only each other together; frozen members
// that no moving member can reach go back to the bed.
//
// The common step is the exponential integrator's, unchanged, over the members only: contacts,
// the bed and freezing are exactly those of the global scheme. Syncs are taken in time order
// from a heap; a step of the members ends early at a sync that engages, so that every grain
// joins the common step at the members' time. The voidage grid is kept up to date grain by
// grain (each sync or member step moves the grain's deposit when it changes cell), instead of
// being computed anew each step. Where grains meet, the syncs are taken one at a time, in time
// order. Where the free grains pass each other (no suspension contacts), a grain's sync depends
// only on the walls, the bed and the voidage of its own column of cells: each column is then a
// *lane* with its own syncs, and the lanes are taken on the engine's threads, each in its own
// time order (local_lanes.cpp). Either way a run is the same whatever the thread count.
//
// Below the lowest instrument (integrator.retire_below_instruments) a grain *retires*: nothing
// there can rise back into an instrument's reach, so it leaves the dynamics and falls freely
// onto a coarse bed (columns one largest grain wide, each raised by the area of the grains
// that land in it at a packing of kBedPacking), where it is drawn without contacts.
//
// The stepper is split by job: local_stepper.cpp (start, the step, the voidage deposits),
// local_coasting.cpp (windows and syncs), local_lanes.cpp (syncs lane by lane, on threads),
// local_membership.cpp (engage, release, settle),
// local_retirement.cpp (the coarse bed), local_checkpoint.cpp (its state in checkpoints, and
// the scheme's promise checked for tests), local_clusters.cpp (what clusters of members on
// steps of their own would save: a report), local_own_steps.cpp (clusters of members on steps
// of their own: integrator.own_steps).

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

#include "core/engine/contact/box_registry.h"
#include "core/engine/forces/drag_evaluator.h"
#include "core/engine/integrate/free_flight.h"
#include "core/engine/schedule/engine_parts.h"
#include "core/engine/schedule/grain_kind.h"
#include "core/engine/schedule/sync_queue.h"
#include "core/engine/state/disjoint_sets.h"
#include "core/model/particles.h"

namespace sedem {

class LocalStepper {
 public:
  // Every grain starts coasting where a window fits; the others engage.
  explicit LocalStepper(EngineParts& parts);
  // One step of the members (the last one shortened to land on `limit`), with every sync due
  // before its end.
  void step(double limit);

  // The grains the state does not hold (coasting, settled, retired), at the engine's time, into
  // the sample's order.
  void write_free_grains(Particles& p) const;
  // Below this height grains leave the dynamics for the coarse bed (0: none).
  double retire_height() const { return retire_height_; }
  // The first broken promise of the scheme, or "" (local_checkpoint.cpp).
  std::string violation() const;
  void save(std::ostream& out) const;
  void load(std::istream& in);
  std::size_t bytes() const;

 private:
  // A member's and a settled grain's box is widened by (1 + kSkin) radii: the skin holds the
  // projection's corrections. A coasting grain's follows its exact path and needs none but
  // against round-off: (1 + kCoastSkin) radii. At half a radius, as the members', two grains
  // falling side by side a radius apart could not both coast, and a quarter of the members in
  // a test's first minute were there for it (docs/results/engine.md, "Thinner coasting boxes,
  // and pairs that leave together").
  static constexpr double kSkin = 0.5;
  static constexpr double kCoastSkin = 0.1;
  // A member's box lets it travel kAllowance radii, and moves with it once it has travelled
  // kReanchor. Re-anchored past kReanchor at a step's end, it travels at most
  // crossing_fraction <= 1 radius in the next step: 2 is the least allowance that holds it (the
  // skin holds the projection's corrections). The boxes' side is in radii, not spacings, so the
  // share of the section they cover grows with the count: at a million grains in sample 5 the
  // members' boxes at 3 radii reached their neighbours' and a third of the grains joined the
  // common step (docs/results/engine.md, "Members' boxes").
  static constexpr double kAllowance = 2.0;
  static constexpr double kReanchor = 1.0;
  // A member's pace radius is integrator.member_box_steps times its travel in the last step over
  // crossing_fraction, if that is less than its own radius, and no less than kLeastPace mean
  // spacings (member_box): in a million grains' first 0.3 s, 0.01 spacings made more steps and
  // 0.05 kept more members (docs/results/engine.md, "Members' boxes by their travel").
  static constexpr double kLeastPace = 0.02;
  double least_pace_ = 0;
  // Relative gap to the terminal velocity of a long window.
  static constexpr double kConverged = 1e-3;
  // Response times of a window still converging.
  static constexpr double kResponses = 8.0;
  // Looks between a window's clear length and the blocked one twice as long, after halving.
  static constexpr int kBisections = 3;
  // Steps between two looks for members that touch nothing (to release them).
  static constexpr std::int64_t kReleaseEvery = 16;
  // Area fraction of the coarse bed (discs packed at random).
  static constexpr double kBedPacking = 0.8;
  static constexpr std::uint32_t kNoMember = 0xFFFFFFFF;
  using Sync = SyncQueue::Sync;
  // Syncs one step takes at most while no member moves: the step then ends at the last one
  // taken. A step is the engine's unit of stopping, and with every grain coasting on short
  // windows (integrator.max_coast_s) one max_step_s could hold 1e8 syncs and minutes of work.
  static constexpr std::size_t kIdleStepSyncs = 1 << 16;

  // The syncs of one lane: a column of voidage cells where the free grains pass each other,
  // every grain where they meet (local_lanes.cpp).
  struct Lane {
    SyncQueue syncs;                    // (t1, id), earliest first
    std::size_t clean_at = 1024;        // queue size past which its stale entries go
    std::vector<std::uint32_t> near;    // scratch of coast
    std::vector<std::uint32_t> failed;  // could not coast on: to join the members
    struct Leaving {
      double t;
      std::uint32_t id;
      FreeFlight::Point at;
    };
    std::vector<Leaving> leaving;  // retiring, or into another lane's column: taken after
    double particle_steps = 0;
    std::int64_t windows = 0;
    std::size_t taken = 0;       // syncs in this round
    double blown_at = HUGE_VAL;  // the first sync that found a non-finite trajectory
    std::uint32_t blown_id = 0;
    double blown_x = 0;
  };
  std::size_t lane_of(double x) const { return lanes_.size() == 1 ? 0 : e_.voidage.column(x); }
  void push_sync(Lane& lane, double t, std::uint32_t id);
  void take_lane(std::size_t l, double target);
  void take_lanes(double target);
  double idle_horizon(double target);
  void count_lanes();
  // Coasting and syncs (local_coasting.cpp).
  // `blocker`, if given: in, a grain whose box may still be in every window's way (checked
  // first, exactly: then no query is made); out, the one in the shortest window's way.
  bool coast(std::uint32_t id, double t, const FreeFlight::Point& p, bool commit,
             Box* needed = nullptr, std::uint32_t* blocker = nullptr);
  bool make_room(std::uint32_t id, double t, const FreeFlight::Point& p);
  void note_ahead(std::uint32_t id, double t, const Box& before, double t0_before);
  bool resync_clear_of(std::uint32_t id, const Box& reach);
  bool passes(std::uint32_t j) const;
  void hold_coasting_box(std::uint32_t id, const Box& box);
  static Box coasting_disc(double x, double y, double diameter);
  FreeFlight flight_of(std::uint32_t id, const FreeFlight::Point& p,
                       DragMemo* memo = nullptr) const;
  double drag_at(std::uint32_t id, const FreeFlight::Point& p, double speed,
                 DragMemo* memo = nullptr) const;
  FreeFlight flight_with(std::uint32_t id, const FreeFlight::Point& p, double c) const;
  bool relax_drag(std::uint32_t id, const FreeFlight::Point& p, FreeFlight& f,
                  DragMemo* memo) const;
  FreeFlight::Point coasting_at(std::uint32_t id, double t) const;
  // Membership of the common step (local_membership.cpp).
  void engage(std::uint32_t id, const FreeFlight::Point& p, bool frozen);
  void wake_around(std::uint32_t id);
  void anchor(std::size_t k);
  void remove_member(std::size_t k);
  void release_members();
  bool leave_together(const std::vector<std::uint32_t>& group);
  Box member_disc(std::size_t k) const;
  void settle_members();
  void index_members();
  Box member_box(std::size_t k) const;
  void note_allowance(std::uint32_t id, std::size_t k);
  // Whether members' boxes have pace radii of their own (EngineParts::allowance).
  bool paced() const { return e_.paced; }
  // Carried steps: lists rebuilt if stale, then the members' step chosen again (the step reads
  // the lists' pairs and margins).
  void fresh_step();
  // The coarse bed (local_retirement.cpp).
  void retire(std::uint32_t id, double t, const FreeFlight::Point& p);
  void retire_members();
  FreeFlight::Point retired_at(std::uint32_t id, double t) const;
  // The voidage grid, kept up to date grain by grain (local_stepper.cpp).
  void move_deposit(std::uint32_t id, double x, double y);

  EngineParts& e_;
  // Each grain is coasting (on its exact free trajectory `flight` from t0 until t1), a
  // member of the common step (in the state, at index member_), or settled (a frozen grain no
  // member can reach, kept out of the state), or retired (below every instrument, falling on
  // flight from t0 onto the coarse bed, to rest at (t1, land_y_)). See GrainKind.
  bool members_changed_ = false;
  std::vector<GrainKind> kind_;
  // A grain's window in one record: a sync reads and writes all of it, and grains of one lane
  // are scattered among the others' ids (in separate arrays the threads taking two lanes wrote
  // into the same cache lines at every sync).
  struct Track {
    FreeFlight flight;  // coasting: from t0; members: anchor of their box in x, y
    double t0 = 0, t1 = 0;
    std::uint32_t deposit_cell = 0;  // the voidage cell holding its weight
  };
  std::vector<Track> track_;
  // The passes over the members read their tracks by sample index, a cache miss each: the
  // track of the member that many places ahead is asked for in advance.
  static constexpr std::size_t kPrefetchAhead = 8;
  void prefetch_track(std::size_t k) const {
    if (k < e_.state.size()) prefetch_grain(e_.state.origin[k]);
  }
  // Likewise a sync asks for the next one's grain while it is taken.
  void prefetch_grain(std::uint32_t id) const {
    const Track* t = &track_[id];
    __builtin_prefetch(t);
    __builtin_prefetch(&t->deposit_cell);
    __builtin_prefetch(&kind_[id]);
  }
  void prefetch_next(SyncQueue& syncs) const {
    if (!syncs.empty()) prefetch_grain(syncs.front().second);
  }
  std::vector<std::uint32_t> member_;
  // Each member's box anchor and voidage cell (copies of its track's flight.x, flight.y and
  // deposit_cell), in the state's order: the passes over the members after each step read them
  // in order, where the track is a cache miss by sample index (the deposits' pass alone was 7 %
  // of a run at 10^6 grains). Kept with the state: engage appends, remove_member moves,
  // index_members reads them again after a re-sort; anchor() and the deposits' pass write both.
  struct MemberTrack {
    double x = 0, y = 0;
    std::uint32_t cell = 0;
  };
  std::vector<MemberTrack> member_track_;
  std::vector<Lane> lanes_;
  int lane_threads_ = 1;
  std::size_t recent_syncs_ = 0;  // taken in the last round of every lane
  // Syncs in a round from which the lanes go on threads (bench: sedem_bench_scale --threads).
  static constexpr std::size_t kThreadedSyncs = 64;
  std::vector<Lane::Leaving> leaving_;  // scratch of take_lanes
  BoxRegistry boxes_;
  std::vector<std::uint32_t> wake_, failed_;  // scratch
  struct Ahead {
    std::uint32_t id;
    double time;
    Box before, after;
    bool widened;
  };
  std::vector<Ahead> ahead_;               // synced within this step, with the box they had
  std::vector<std::uint32_t> ahead_slot_;  // per grain: its latest entry in ahead_
  // Per grain: the one whose box kept it from leaving the members at its last try (a hint:
  // kept in no checkpoint, it changes no result).
  std::vector<std::uint32_t> blocker_;
  std::vector<Ahead> widened_;  // synced ahead of a shortened step: boxes to narrow later
  struct Room {
    std::uint32_t id;
    FreeFlight::Point at;  // where it is at the sync that moves it
    Box before;            // its box until then
    double t0;             // its window's start until then
  };
  std::vector<Room> room_;            // scratch of make_room
  std::vector<std::uint32_t> found_;  // scratch of wake_around
  // Scratch of release_members: the members touching nothing, their shortest windows, the
  // groups of those that stay and hold each other (by index in `free`), and the boxes and
  // tracks a group held before trying to leave together.
  struct Release {
    std::vector<std::uint32_t> free, group;
    std::vector<Box> shortest;
    std::vector<std::uint8_t> loose, whole;
    DisjointSets groups;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> by_group;  // (root, member)
    struct Held {
      Box box;
      Track track;
    };
    std::vector<Held> held;
    std::size_t bytes() const {
      auto cap = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
      return cap(free) + cap(group) + cap(shortest) + cap(loose) + cap(whole) + groups.bytes() +
             cap(by_group) + cap(held);
    }
  };
  Release release_;
  // What clusters of members on steps of their own would save (local_clusters.cpp), looked at
  // every kClusterLookEvery steps: the scratch of the look.
  void look_at_clusters();
  static constexpr std::int64_t kClusterLookEvery = 64;
  struct Clusters {
    DisjointSets sets;            // members joined by overlapping boxes
    std::vector<double> rate;     // by state index: the step rule's (Integrator::own_rates)
    std::vector<double> fastest;  // by root: the cluster's fastest member's rate
    std::vector<double> moving;   // by root: its moving members
    std::size_t bytes() const {
      return sets.bytes() +
             (rate.capacity() + fastest.capacity() + moving.capacity()) * sizeof(double);
    }
  };
  Clusters clusters_;
  // Own steps (integrator.own_steps; local_own_steps.cpp): clusters of members linked by their
  // candidate lists, a slow one lagging the common step.
  bool own_steps_ = false;
  // Moving members below which no cluster lags, where the passes over the members and the lists
  // that lagging takes are most of a step. Not tuned: at 256 the tests' crowd of 1 500 grains had
  // no lagging cluster; at 64 it has.
  static constexpr std::size_t kOwnStepsFrom = 64;
  // By sample index: the time a lagging member is at (its last step's end), kInSync for the
  // others; member_at_ holds a copy in the state's order (beside the members' tracks, not in
  // them: a wider MemberTrack slowed every pass over the members, own steps on or off).
  static constexpr double kInSync = -1;
  std::vector<double> at_, member_at_;
  double lag_of(std::size_t k) const {
    const double at = member_at_[k];
    return at < 0 ? 0.0 : e_.time - at;
  }
  void set_at(std::size_t k, double at) { at_[e_.state.origin[k]] = member_at_[k] = at; }
  std::size_t lagging_ = 0;    // members lagging now
  double lag_cap_ = HUGE_VAL;  // the longest common step no lagging cluster's own step forbids
  struct OwnSteps {
    DisjointSets sets;                // moving members linked by their lists' pairs, by state index
    std::vector<double> rate;         // by state index: its rate under the step rule
    std::vector<double> horizon;      // by root: its own step (its fastest member's)
    std::vector<double> most, least;  // by root: its members' largest and smallest lag
    std::vector<std::uint32_t> part_of;  // by state index: its part in this run, or kNoMember
    // By row of the lists: a moving member whose cluster holds every moving member of the row
    // (kNoMember: none; kMixedRow: a frozen grain's row whose moving partners may lie in two),
    // so that a run finds each part's rows by cluster, not by every pair.
    std::vector<std::uint32_t> row_member;
    std::vector<std::uint32_t> cluster_size;      // by root: its moving members
    std::vector<std::uint32_t> tally, root_part;  // by root, scratch
    static constexpr std::uint32_t kMixedRow = kNoMember - 1;
    std::vector<std::uint32_t> moving;  // state indices of the moving members
    std::vector<std::uint8_t> aside;    // by sample index: held still in the part running
    std::vector<std::pair<double, std::uint32_t>> catching;  // (lag, state index), scratch
    std::vector<std::uint32_t> moved;                        // settle_lags' scratch
    std::vector<std::uint32_t> rerate;  // state indices anchored since the rates were taken
    struct Part {
      double dt = 0;
      int phase = 1;  // 0: ends at the step's start (a catch-up before it), 1: at its end
      std::vector<std::uint32_t> members, rows;
    };
    std::vector<Part> parts;
    std::size_t used = 0;  // parts of this run
    // What the clusters were found from: the lists' builds and rows, the members.
    bool valid = false, rates_valid = false;
    std::int64_t builds = 0;
    std::size_t rows = 0, members = 0;
    std::size_t clean_rows = 0;  // rows up to here link no two lags (links_two_lags)
    // The lagging clusters the members' step left (their lag, their own step), while the lists
    // link no two lags; lagging_stale after a checkpoint is loaded (the list is not kept).
    struct Lagging {
      double at, horizon;
    };
    std::vector<Lagging> lagging_roots;
    bool lagging_stale = true;
    std::vector<std::uint8_t> mark;  // by root, scratch
    std::size_t bytes() const;
  };
  OwnSteps own_;
  void find_clusters();
  bool links_two_lags();
  // The part of this run that steps over dt and ends at the step's start (phase 0) or end (1),
  // added if there is none yet.
  std::size_t part_of_dt(double dt, int phase);
  // Runs the parts added since own_.used was zeroed, phase 0 first; returns the member-steps
  // taken (a blow-up is reported at time `at`).
  std::size_t run_parts(double at);
  // The members' step over dt (own steps), in parts: `all` brings every cluster to its end.
  // Returns the member-steps taken.
  std::size_t advance_own(double dt, bool all, double at);
  // Clusters holding members of different lags (a list now links them) catch up, and at a
  // step's start (dt > 0) those that a step of dt would carry past their own step, with what
  // their moves bring (new boxes, joiners, a rebuild); then lag_cap_. True if any moved (the
  // step is then chosen again).
  bool settle_lags(double dt);
  // After members moved outside the members' step: their voidage deposits, the lists'
  // margins, their boxes.
  void after_own_moves(const std::vector<std::uint32_t>& moved);
  void reanchor_if_used(std::size_t k);
  double registry_cell_ = 1e-3, travel_ = 1e-3;
  std::size_t settled_ = 0;
  double retire_height_ = 0;    // 0: no grain retires
  std::vector<double> land_y_;  // retired grains: the height of their centre on the bed
  std::vector<double> bed_;     // the coarse bed: the height of each column's top
  double bed_column_ = 1e-4;    // the columns' width
};

}  // namespace sedem
