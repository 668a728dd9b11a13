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
  std::size_t cell_count() const { return voidage_.size(); }
  std::size_t bytes() const { return (3 * voidage_.size() + partial_.size()) * sizeof(double); }

 private:
  std::size_t cell_of(double x, double y) const {
    long c = long((x + half_width_) * inverse_cell_), r = long(y * inverse_cell_);
    c = c < 0 ? 0 : (c >= columns_ ? columns_ - 1 : c);
    r = r < 0 ? 0 : (r >= rows_ ? rows_ - 1 : r);
    return std::size_t(r * columns_ + c);
  }
  double inverse_cell_ = 1, half_width_ = 0, cell_volume_ = 1, min_voidage_ = 0;
  long columns_ = 1, rows_ = 1;
  int threads_ = 1;
  std::vector<double> voidage_, log_voidage_, hindrance_, partial_;
};

}  // namespace sedem
