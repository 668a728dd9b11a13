#include "core/scene/stage_keys.h"

namespace sedem {

void describe(ForcesConfig& c, Schema& s) {
  s.flag("forces.weight", &c.weight, "Gravity on every particle.");
  s.flag("forces.buoyancy", &c.buoyancy, "Hydrostatic force of the fluid on every particle.");
  s.choice("forces.drag", &c.drag, {"di_felice", "stokes", "off"},
           "Drag law: Di Felice with local voidage (Eqs. 7-9), plain Stokes (Eq. 11), or none.");
  s.flag("forces.contact", &c.contact, "Penalty contact between particles and with the walls.");
  s.flag("forces.suspension_contacts", &c.suspension_contacts,
         "false: grains in the suspension pass each other and meet only the walls (needs "
         "local steps and retirement below the instruments, so that the bed is the coarse "
         "one). Each simulated grain stands for many real ones spread through the slab, so "
         "its collisions in the section grow with the simulated count; the voidage of the "
         "drag carries the suspension's hindrance. See docs/engine.md.");
  s.number("forces.stiffness_normal", &c.stiffness_normal, "N/m", 1, 1e-6, 1e9,
           "K_N, normal penalty spring (paper: 1e3).");
  s.number("forces.stiffness_tangential", &c.stiffness_tangential, "N/m", 1, 1e-6, 1e9,
           "K_T, tangential penalty spring (paper: 1e3).");
  s.number("forces.friction", &c.friction, "", 1, 0, 10, "Coulomb friction coefficient mu_c.");
  s.flag("forces.lubrication", &c.lubrication,
         "Squeeze-film repulsion between close pairs (Eq. 10).");
  s.number("forces.lubrication_intensity", &c.lubrication_intensity, "", 1, 0, 1e6,
           "Intensity of Eq. 10 (paper: 10).");
  s.number("forces.lubrication_range", &c.lubrication_range, "", 1, 1e-3, 1e6,
           "Range of Eq. 10, in inverse particle radii (paper: 10).");
  s.number("forces.voidage_cell_mm", &c.voidage_cell, "mm", 1e-3, 1e-3, 1e3,
           "Side of the square cells in which the local voidage of the drag is computed.")
      .min_exclusive = true;
  s.number("forces.min_voidage", &c.min_voidage, "", 1, 0.01, 1,
           "Floor on the grid's voidage, where statistical weights pack more than a bed.");
  s.flag("forces.voidage_excludes_self", &c.voidage_excludes_self,
         "The voidage a grain's drag feels leaves out the grain's own statistical weight, which "
         "with few heavily weighted particles would pack its cell on its own.");
}

void describe(IntegratorConfig& c, Schema& s) {
  s.choice("integrator.method", &c.method, {"explicit", "exponential"},
           "explicit: symplectic Euler, the paper's step rule (its former name, reference, is "
           "still read); exponential: exact drag update, large stable steps.");
  s.alias("integrator.method", kFormerExplicitName, "explicit");
  s.number("integrator.step_factor", &c.step_factor, "", 1, 1e-6, 1e9,
           "Time step as a multiple of the smallest response time t_tr (paper: 0.1).");
  s.flag("integrator.adaptive", &c.adaptive,
         "explicit: grow the step once every particle is at terminal velocity (Sect. 4.6).");
  s.number("integrator.fast_step_factor", &c.fast_step_factor, "", 1, 1e-6, 1e9,
           "exponential: upper bound on the step as a multiple of the smallest response time "
           "t_tr.");
  s.number("integrator.crossing_fraction", &c.crossing_fraction, "", 1, 0, 1,
           "exponential: the step lets no moving grain travel more than this fraction of its "
           "radius, so none passes through another.")
      .min_exclusive = true;
  s.flag("integrator.freeze_settled", &c.freeze_settled,
         "Freeze particles resting in the bed below the lowest instrument.");
  s.number("integrator.max_step_s", &c.max_step, "s", 1, 1e-12, 1e6, "Upper bound on the step.");
  s.flag("integrator.local_steps", &c.local_steps,
         "exponential: a grain that can touch nothing follows its exact free trajectory over a "
         "window of its own (space-time boxes keep windows apart), and only grains near a "
         "contact, a wall or the bed share the common step. Off: every grain takes the common "
         "step.");
  s.number("integrator.carried_fraction", &c.carried_fraction, "", 1, 0, 1,
           "exponential with local_steps (ignored otherwise): a grain held against a coarser one "
           "(directly or through other grains) may travel this fraction of the coarsest one's "
           "radius a step, if that is more than crossing_fraction of its own; every pair that "
           "could meet still closes by at most its gap plus crossing_fraction of its two radii, "
           "so none passes through another. 0: every grain is limited by its own radius, and a "
           "fine grain pushed by a coarse one sets the common step of every member.");
  s.flag("integrator.carried_substeps", &c.carried_substeps,
         "with carried_fraction > 0: the grains a step would carry further than crossing_fraction "
         "of their own radius, and every member that could reach them within it, take sub-steps "
         "of their own inside it, each within crossing_fraction of their own radius, the others "
         "held still (no pair of the two can meet within the step). Contacts are then resolved "
         "as with every grain at its own radius, at the carried steps' count of common steps.");
  s.flag("integrator.own_steps", &c.own_steps,
         "exponential with local_steps, suspension contacts and no carried steps: the members "
         "fall into clusters that their candidate lists link (no pair of two clusters can meet "
         "before the lists are rebuilt), and a cluster whose own fastest member allows twice the "
         "common step or more lags it, taking one step of its own (at most what its own members' "
         "rule allows) when it must. Every cluster catches up at each reading, at every 16th "
         "common step and when another links to it; none lags below 64 moving members. Off: "
         "every member takes the common step.");
  s.flag("integrator.retire_below_instruments", &c.retire_below,
         "exponential with local_steps and at least one instrument: a grain that falls below "
         "the lowest instrument (less 1 cm) leaves the simulation and falls freely onto a coarse "
         "bed (columns one largest grain wide, packed at 0.8, each grain in the lowest of the five "
         "nearest), where it is drawn without "
         "contacts. No reading can change: nothing there rises back to an instrument.");
  s.number("integrator.max_coast_s", &c.max_coast, "s", 1, 1e-6, 1e6,
           "exponential with local_steps: the longest window a free grain coasts with its drag "
           "(and the voidage it feels) held constant.")
      .min_exclusive = true;
  s.number("integrator.coast_travel", &c.coast_travel, "", 1, 0, 1e3,
           "exponential with local_steps: the longest travel of a free grain's window, in mean "
           "spacings of the particles (where the free grains pass each other, no less than a "
           "voidage cell). Longer windows mean fewer looks at each grain; where many grains "
           "crowd the common step, more of their boxes meet theirs.")
      .min_exclusive = true;
  s.number("integrator.coast_drag_change", &c.coast_drag_change, "", 1, 0, 1,
           "exponential with local_steps and Di Felice drag: a free grain still far from its "
           "terminal velocity coasts on a window of a few response times, its drag taken anew "
           "at their end, unless its drag at the terminal velocity differs from the one it holds "
           "by at most this fraction (a fine grain's drag hardly depends on its speed). 0: the "
           "window is always cut.");
  s.number("integrator.member_box_steps", &c.member_box_steps, "", 1, 0, 1e6,
           "exponential with local_steps: a grain on the common step holds a box it cannot leave "
           "before it is looked at again, which lets it travel 2 of its radii, and a step moves "
           "it at most crossing_fraction of one. Where its radius is more than a fiftieth of the "
           "mean spacing, this many times its travel in the last step, over crossing_fraction, "
           "stands for its radius if that is less (but no less than the fiftieth). Smaller boxes "
           "meet fewer grains' boxes, so fewer grains join the common step; the step can grow by "
           "this factor each time a box moves. 0: every grain's own radius. 0 or at least 2.");
  s.integer("integrator.threads", &c.threads, 0, 1024,
            "Worker threads; 0 uses every core. With local_steps they take the syncs' lanes "
            "where the free grains pass each other (forces.suspension_contacts = false); where "
            "grains meet, the members' step when 256 or more. Below 2048 particles, one. With "
            "local_steps any count gives the same results.");
}

}  // namespace sedem
