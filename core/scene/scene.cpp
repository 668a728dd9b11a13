#include "core/scene/scene.h"

#include "core/scene/stage_keys.h"

namespace sedem {

static void describe(Fluid& f, Schema& s) {
  s.number("fluid.density", &f.density, "kg/m^3", 1, 500, 2000, "Fluid density (water: 1000).");
  s.number("fluid.viscosity", &f.viscosity, "Pa*s", 1, 1e-6, 10,
           "Dynamic viscosity (water at 20 C: 1.0e-3).")
      .min_exclusive = true;
  s.number("fluid.gravity", &f.gravity, "m/s^2", 1, 0, 100, "Gravitational acceleration.");
}

static void describe(Cylinder& c, Schema& s) {
  s.number("cylinder.height_m", &c.height, "m", 1, 1e-4, 10, "H, height of the suspension.");
  s.number("cylinder.diameter_m", &c.diameter, "m", 1, 1e-4, 10, "B, inner diameter.");
  s.number("cylinder.section_fraction", &c.section_fraction, "", 1, 1e-6, 1,
           "Share of the cylinder the 2D section stands for (two 1-degree wedges: 1/180).");
}

static void describe(OutputConfig& o, Schema& s) {
  s.number("output.interval_s", &o.interval, "s", 1, 1e-6, 1e7,
           "Simulated time between snapshots.");
  s.flag("output.particles", &o.particles, "Write the particles.pvd series for ParaView.");
  s.flag("output.frames", &o.frames,
         "Render a PNG of the column at every snapshot, and Fig. 11 (its panels at "
         "output.fig11_times_min).");
  s.flag("output.fields", &o.fields,
         "Write fields.pvd: layer suspension density and concentration at every snapshot.");
  s.choices("output.figure_formats", &o.figure_formats, {"png", "svg", "pdf"},
            "Formats of every figure (Figs. 11-18, summaries): any of png, svg, pdf, as "
            "\"png,pdf\" or [\"png\", \"pdf\"]. SVG and PDF are vector graphics for papers.");
  s.integer("output.figure_width_px", &o.figure_width_px, 200, 20000,
            "Width of a PNG figure in pixels (its height follows the figure's shape).");
  s.number("output.figure_dpi", &o.figure_dpi, "px/in", 1, 36, 2400,
           "Pixels per inch of the PNG figures: a figure is figure_width_px / figure_dpi "
           "inches wide, and its SVG and PDF have that size.");
  s.flag("output.vector_figures", &o.vector_figures,
         "Former switch, still read: true adds svg and pdf to output.figure_formats.");
  s.list("output.fig11_times_min", &o.fig11_times, "min", 60, 0, 1e6,
         "Times of Fig. 11's panels, the column and its zooms (paper: 1, 5, 15 min).");
  s.integer("output.frame_width", &o.frame_width, 16, 8192, "Frame width, pixels.");
  s.integer("output.frame_height", &o.frame_height, 16, 8192, "Frame height, pixels.");
}

Schema Scene::schema() {
  Schema s;
  s.text("name", &name, "A name for the scene, used in titles and run.json.");
  s.number("run.end_time_s", &end_time, "s", 1, 0, 1e7, "Simulated duration of the test.");
  s.number("run.checkpoint_interval_s", &checkpoint_interval, "s", 1, 0, 1e6,
           "Wall-clock time between checkpoints written during the run (the first after 10 s, "
           "or this if shorter): a kill or a power cut loses at most this much work (--resume "
           "goes on from the last one); 0: only when stopped by Ctrl-C or SIGTERM.");
  describe(fluid, s);
  describe(cylinder, s);
  describe(sample, s);
  describe(forces, s);
  describe(integrator, s);
  describe(instruments, s);
  describe(output, s);
  return s;
}

}  // namespace sedem
