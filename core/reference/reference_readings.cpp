#include "core/reference/reference_readings.h"

#include "core/instruments/instrument_panel.h"
#include "core/scene/scene.h"

namespace sedem {

ReferenceOptions reference_options(const Scene& scene) {
  ReferenceOptions o;
  o.settling = reference_settling(scene.instruments.reference_settling);
  o.richardson_zaki_exponent = scene.instruments.reference_richardson_zaki_exponent;
  o.bed_packing = scene.instruments.reference_bed_packing;
  return o;
}

std::vector<TestReadings> reference_readings(const Scene& scene, const Sample& sample) {
  return reference_readings(scene, sample, make_reference(scene, sample, reference_options(scene)));
}

std::vector<TestReadings> reference_readings(const Scene& scene, const Sample& sample,
                                             const ReferenceSolution& reference) {
  InstrumentPanel panel(scene, sample);
  for (double t : panel.reading_times())
    panel.observe(t, reference.layer_fields(t, panel.layers(), scene.fluid));
  return panel.readings();
}

}  // namespace sedem
