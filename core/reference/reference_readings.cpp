#include "core/reference/reference_readings.h"

#include "core/instruments/instrument_panel.h"

namespace sedem {

ReferenceOptions reference_options(const TestSetup& setup) {
  ReferenceOptions o;
  o.settling = reference_settling(setup.instruments.reference_settling);
  o.richardson_zaki_exponent = setup.instruments.reference_richardson_zaki_exponent;
  o.bed_packing = setup.instruments.reference_bed_packing;
  return o;
}

std::vector<TestReadings> reference_readings(const TestSetup& setup, const Sample& sample) {
  return reference_readings(setup, sample, make_reference(setup, sample, reference_options(setup)));
}

std::vector<TestReadings> reference_readings(const TestSetup& setup, const Sample& sample,
                                             const ReferenceSolution& reference) {
  InstrumentPanel panel(setup, sample);
  for (double t : panel.reading_times())
    panel.observe(t, reference.layer_fields(t, panel.layers(), setup.fluid));
  return panel.readings();
}

}  // namespace sedem
