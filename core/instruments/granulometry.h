#pragma once

#include <string>
#include <vector>

#include "core/instruments/buoyancy_sphere.h"
#include "core/instruments/hydrometer.h"
#include "core/instruments/pipette.h"
#include "core/model/sample.h"

namespace sedem {

// One reading of a test: its point (phi_o, w_o) of the grading curve and the instrument's
// own quantities, in SI, named by TestReadings::extra_columns.
struct Reading {
  double time = 0;           // s
  double diameter = 0;       // phi_o, m
  double percent_finer = 0;  // w_o, %
  std::vector<double> extra;
};

struct TestReadings {
  std::string test;                        // "hydrometer" | "buoyancy" | "pipette"
  std::vector<std::string> extra_columns;  // with their unit, e.g. "tip_depth_m"
  std::vector<Reading> rows;
};

TestReadings to_readings(const std::vector<HydrometerReading>& readings);
TestReadings to_readings(const std::vector<BuoyancyReading>& readings);
TestReadings to_readings(const std::vector<PipetteReading>& readings);

struct GradingPoint {
  double diameter = 0;       // m
  double percent_finer = 0;  // %
};

// The sample's true curve: at each class diameter, the mass percent of grains of that
// diameter or smaller.
std::vector<GradingPoint> true_grading_curve(const std::vector<SizeClass>& classes);
// The true percent finer at any diameter: a step function of the discrete sample (the
// grains of diameter <= d, the w_o of Sect. 4.1).
double true_percent_finer(const std::vector<SizeClass>& classes, double diameter);

// Error: the largest |w_o(DEM) - w_o(reference)| over the test's times, percentage points.
// The two must hold the same times. NaN when there is no reading (or one is no number): a test
// that read nothing has no error, and is never reported as a perfect 0.
double curve_error(const TestReadings& dem, const TestReadings& reference);
// Bias: the largest |w_o(reference) - true percent finer at the reference's phi_o|; NaN
// likewise.
double curve_bias(const TestReadings& reference, const std::vector<SizeClass>& classes);

struct TestComparison {
  std::string test;
  TestReadings dem, reference;
  double error = 0;  // percentage points, DEM against reference
  double bias = 0;   // percentage points, reference against the true curve
};

struct Granulometry {
  std::vector<GradingPoint> true_curve;
  std::vector<TestComparison> tests;
};

// Pairs each DEM test with the reference test of the same name.
Granulometry compare(const std::vector<TestReadings>& dem,
                     const std::vector<TestReadings>& reference,
                     const std::vector<SizeClass>& classes);

}  // namespace sedem
