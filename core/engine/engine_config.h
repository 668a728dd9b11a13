#pragma once

#include <cstdint>
#include <string>

namespace sedem {

// Which forces act (Sect. 3, 4.2). Each can be switched off in a scene.
struct ForcesConfig {
  bool weight = true;
  bool buoyancy = true;
  std::string drag = "di_felice";  // di_felice | stokes | off
  bool contact = true;
  bool suspension_contacts = true;    // false: free grains pass each other (local steps only)
  double stiffness_normal = 1e3;      // K_N, N/m
  double stiffness_tangential = 1e3;  // K_T, N/m
  double friction = 0.5;              // Coulomb mu_c
  bool lubrication = false;
  double lubrication_intensity = 10;  // the first 10 of Eq. 10
  double lubrication_range = 10;      // the second 10 of Eq. 10
  double voidage_cell = 4e-3;         // m, side of the square cells of the voidage grid
  double min_voidage = 0.3;           // floor on the grid's voidage (a packed bed's ~0.4)
  bool voidage_excludes_self = true;  // a grain's own weight is not in the voidage it feels
};

// How Eq. 5 is advanced in time (Sect. 4.6).
struct IntegratorConfig {
  std::string method = "exponential";  // explicit | exponential (see integrator_method)
  double step_factor = 0.1;            // explicit: dt = factor * min t_tr (paper: 0.1)
  bool adaptive = true;                // explicit: the growth rule of Sect. 4.6
  double fast_step_factor = 1e5;       // exponential: dt <= factor * min t_tr
  double crossing_fraction = 0.8;      // exponential: dt <= fraction * r / speed, every grain
  double max_step = 1.0;               // s, upper bound on any step
  bool local_steps = true;             // exponential: each free grain on its own window
  // local steps: a grain held against a coarser one may travel this fraction of the coarser
  // one's radius a step (0: its own radius limits it, crossing_fraction)
  double carried_fraction = 0;
  // with carried steps: the grains carried further than their own radius allows take exact
  // sub-steps of their own within the step
  bool carried_substeps = false;
  // local steps where grains meet: each cluster of members (linked by their candidate lists)
  // steps at its own fastest member's rule, a slow one lagging the common step
  bool own_steps = false;
  double max_coast = 60.0;  // s, longest window of a coasting grain
  // local steps: the longest travel of a coasting grain's window, in mean spacings (where the
  // free grains pass each other, no shorter than a voidage cell)
  double coast_travel = 2.0;
  // local steps, Di Felice drag: a coasting grain still far from its terminal velocity keeps
  // its window past a few response times if its drag at that velocity differs from the one it
  // holds by at most this fraction (0: its window is always cut)
  double coast_drag_change = 1e-3;
  // local steps: where a member's radius is more than a fiftieth of the mean spacing, its box's
  // pace radius is this many times its travel in the last step over crossing_fraction, if that
  // is less (0: its own radius)
  double member_box_steps = 4;
  bool freeze_settled = true;  // freeze resting particles below every instrument
  bool retire_below = true;    // local steps: grains below every instrument land analytically
  std::int64_t threads = 0;    // 0: all cores
};

// The integrator integrator.method names. Scenes and run records written before the explicit
// integrator was renamed say "reference" (the word now names only the continuum reference
// solution): it is read as "explicit" (Schema::alias), and the value may still hold it.
enum class IntegratorMethod { explicit_euler, exponential };
IntegratorMethod integrator_method(const IntegratorConfig& config);

// The name the explicit integrator had before (scenes and run records may still say it).
inline constexpr const char* kFormerExplicitName = "reference";

}  // namespace sedem
