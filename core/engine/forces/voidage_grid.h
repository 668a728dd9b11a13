#pragma once

// Local voidage for the Di Felice drag (Eqs. 7-9): eps = 1 - sum(weight (pi/6) d^3) /
// (cell area * h_z) over square cells of the section, with h_z the slab thickness that makes
// the section stand for its share of the cylinder. The statistical weights make eps refer to
// the real sample whatever the simulated count. Piecewise constant per cell; each thread
// deposits into its own copy, reduced in thread order (deterministic for a thread count).

#include <cstddef>
#include <vector>

namespace sedem {

class VoidageGrid {
 public:
  void configure(double cell, double half_width, double height, double slab_thickness,
                 double min_voidage, int threads);
  void compute(std::size_t n, const double* x, const double* y, const double* diameter,
               const double* weight);
  double at(double x, double y) const { return voidage_[cell_of(x, y)]; }
  // ln(eps) of the cell at (x, y), kept alongside so that eps^a costs one exp.
  double log_at(double x, double y) const { return log_voidage_[cell_of(x, y)]; }
  // The same by cell index, and eps^-1.7 (the Di Felice drag's factor at low Re), per cell.
  std::size_t cell(double x, double y) const { return cell_of(x, y); }
  double voidage(std::size_t c) const { return voidage_[c]; }
  double log_voidage(std::size_t c) const { return log_voidage_[c]; }
  double hindrance(std::size_t c) const { return hindrance_[c]; }
  double min_voidage() const { return min_voidage_; }
  // The voidage of cell c without a grain of `own_volume` (its weight times its volume) that
  // lies there. A grain standing for many real ones would otherwise hinder itself: at 1000
  // particles in a sample, one alone makes ~3 % solids in a 4 mm cell. Leaving it out makes
  // the estimate unbiased for a homogeneous suspension (the others are then what surrounds it).
  double excluding(std::size_t c, double own_volume) const {
    const double eps = 1.0 - solid_[c] + own_volume * inverse_volume_;
    return eps < min_voidage_ ? min_voidage_ : (eps > 1.0 ? 1.0 : eps);
  }
  std::size_t cell_count() const { return voidage_.size(); }
  // The column of cells x lies in, and how many there are: grains in different columns do not
  // see each other's deposits (local time stepping takes their syncs apart).
  std::size_t column(double x) const {
    const long c = long((x + half_width_) * inverse_cell_);
    return std::size_t(c < 0 ? 0 : (c >= columns_ ? columns_ - 1 : c));
  }
  std::size_t columns() const { return std::size_t(columns_); }
  // Local time stepping keeps the grid up to date grain by grain instead of computing it
  // anew each step: a grain's weighted volume (weight * volume, negative to take it out)
  // enters or leaves cell c, whose voidage is then recomputed.
  void deposit(std::size_t c, double weighted_volume);
  // Solid fractions per cell, for checkpoints (set_solid recomputes the voidage from them).
  const std::vector<double>& solid() const { return solid_; }
  void set_solid(const std::vector<double>& solid);
  std::size_t bytes() const { return (4 * voidage_.size() + partial_.size()) * sizeof(double); }

 private:
  void refresh(std::size_t c);
  std::size_t cell_of(double x, double y) const {
    long r = long(y * inverse_cell_);
    r = r < 0 ? 0 : (r >= rows_ ? rows_ - 1 : r);
    return std::size_t(r * columns_) + column(x);
  }
  double inverse_cell_ = 1, half_width_ = 0, cell_volume_ = 1, inverse_volume_ = 1,
         min_voidage_ = 0;
  long columns_ = 1, rows_ = 1;
  int threads_ = 1;
  std::vector<double> voidage_, log_voidage_, hindrance_, partial_;
  std::vector<double> solid_;  // solid fraction per cell, not floored
};

}  // namespace sedem
