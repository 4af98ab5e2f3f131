// Piecewise-constant densities for importance sampling (pbrt's Distribution1D
// and Distribution2D), on plain numbers: a domain [0, 1) or [0, 1)² cut into
// equal cells, each drawn in proportion to its weight and uniformly inside.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "safegi/cpu_renderer/kernel_math.hpp"

namespace safegi::render {

class Distribution1D {
 public:
  // Weights must be non-negative; all zero is drawn uniformly.
  explicit Distribution1D(std::vector<Real> weights) : weights_(std::move(weights)), cdf_(weights_.size() + 1, 0) {
    const size_t n = weights_.size();
    for (size_t i = 0; i < n; ++i) cdf_[i + 1] = cdf_[i] + weights_[i] / static_cast<Real>(n);
    total_ = cdf_[n];
    for (size_t i = 1; i <= n; ++i) cdf_[i] = total_ > 0 ? cdf_[i] / total_ : static_cast<Real>(i) / static_cast<Real>(n);
    cdf_[n] = 1;
  }

  size_t size() const { return weights_.size(); }
  // The mean weight: the integral of the unnormalised function over [0, 1).
  Real integral() const { return total_; }

  // A point x in [0, 1) and its density; `cell` is where it fell.
  Real sample(Real u, Real& density, size_t& cell) const {
    auto above = std::upper_bound(cdf_.begin(), cdf_.end(), u);
    cell = static_cast<size_t>(std::clamp<std::ptrdiff_t>(above - cdf_.begin() - 1, 0, static_cast<std::ptrdiff_t>(size()) - 1));
    const Real width = cdf_[cell + 1] - cdf_[cell];
    const Real inside = width > 0 ? (u - cdf_[cell]) / width : Real(0.5);
    density = this->density(cell);
    return std::min((static_cast<Real>(cell) + inside) / static_cast<Real>(size()), Real(1) - kernel::gamma(1));
  }
  // The density at any point of `cell` (with respect to length on [0, 1)).
  Real density(size_t cell) const {
    return total_ > 0 ? weights_[cell] / total_ : Real(1);
  }
  size_t cell_of(Real x) const {
    return static_cast<size_t>(std::clamp<std::ptrdiff_t>(static_cast<std::ptrdiff_t>(x * static_cast<Real>(size())), 0,
                                                          static_cast<std::ptrdiff_t>(size()) - 1));
  }

 private:
  std::vector<Real> weights_;
  std::vector<Real> cdf_;
  Real total_ = 0;
};

// Rows (v) by their total weight, then a column (u) within the row.
class Distribution2D {
 public:
  // weights[v * width + u], row after row.
  Distribution2D(const std::vector<Real>& weights, int width, int height) : marginal_(row_totals(weights, width, height)) {
    for (int v = 0; v < height; ++v)
      rows_.emplace_back(std::vector<Real>(weights.begin() + v * width, weights.begin() + (v + 1) * width));
  }

  // A point (u, v) in [0, 1)² and its density with respect to area on [0, 1)².
  void sample(Real u1, Real u2, Real& u, Real& v, Real& density) const {
    Real row_density, column_density;
    size_t row, column;
    v = marginal_.sample(u2, row_density, row);
    u = rows_[row].sample(u1, column_density, column);
    density = row_density * column_density;
  }
  Real density(Real u, Real v) const {
    size_t row = marginal_.cell_of(v);
    return marginal_.density(row) * rows_[row].density(rows_[row].cell_of(u));
  }

 private:
  static std::vector<Real> row_totals(const std::vector<Real>& weights, int width, int height) {
    std::vector<Real> totals(height, 0);
    for (int v = 0; v < height; ++v)
      for (int u = 0; u < width; ++u) totals[v] += weights[v * width + u] / static_cast<Real>(width);
    return totals;
  }

  Distribution1D marginal_;
  std::vector<Distribution1D> rows_;
};

}  // namespace safegi::render
