#include "vicc_glyphs/render/multigrid.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "banded_cholesky.hpp"
#include "multigrid_levels.hpp"
#include "vicc_glyphs/render/pixel_buffer.hpp"

namespace vicc_glyphs {
namespace multigrid_detail {
namespace {

// A pixel's values. Colour is stored as four floats (the fourth always zero) in a GCC/Clang
// vector type, so that every per-pixel operation is one 4-wide SIMD instruction; a single
// channel (the blur field) is a plain float.
typedef float Float4 __attribute__((vector_size(16)));

template <int C>
using PixelValue = std::conditional_t<C == 3, Float4, float>;

// What the conjugate-gradient loop of the finest level recorded (see MultigridReport).
struct FineProgress {
  int iterations = 0;
  bool converged = false;
  std::vector<double> residuals, error_estimates, updates;
};

template <int C>
class Multigrid {
  using Px = PixelValue<C>;
  using Field = render_detail::PixelVector<Px>;
  // Dot products per channel, in double: a level can have 10^7 pixels.
  using Sum = std::array<double, C>;

 public:
  // Builds the hierarchy for `problem`, reusing the memory of the previous solve.
  void prepare(const GridProblem& problem, const MultigridOptions& options) {
    problem_ = &problem;
    options_ = options;
    makeFineLevel(problem, fine_);
    free_count_ = static_cast<size_t>(std::count_if(problem.fixed.begin(), problem.fixed.end(),
                                                    [](std::uint8_t f) { return !f; }));
    const std::vector<std::pair<int, int>> sizes =
        levelSizes(problem.width, problem.height, options.coarsest_size);
    const size_t count = sizes.size();
    coarse_.resize(count - 1);
    transfers_.resize(count - 1);
    u_.resize(count);
    f_.resize(count);
    Stencil regular = kFineRegularStencil;
    for (size_t l = 1; l < count; ++l) {
      CoarseLevel& coarse = coarse_[l - 1];
      resizeCoarseLevel(sizes[l].first, sizes[l].second, coarse);
      regular = l == 1 ? coarsen(fine_, regular, transfers_[0], coarse, flags_)
                       : coarsen(coarse_[l - 2], regular, transfers_[l - 1], coarse, flags_);
      allocateField(coarse.size, coarse.stride, coarse.height, u_[l]);
      allocateField(coarse.size, coarse.stride, coarse.height, f_[l]);
    }
    allocateField(fine_.size, fine_.stride, fine_.height, u_[0]);
    for (Field* field : {&r_, &z_, &p_, &ap_}) {
      allocateField(fine_.size, fine_.stride, fine_.height, *field);
    }
    if (balance_) labelFreeComponents(fine_, components_);
    if (count == 1) {
      factoriseCoarsest(fine_);
    } else {
      factoriseCoarsest(coarse_.back());
    }
  }

  // FMG, then preconditioned conjugate gradients on the finest level.
  void solve(float* values, MultigridReport* report) {
    const int coarsest = levelCount() - 1;
    setDirichletValues();
    if (coarsest > 0) {
      // The start is q + P u_1: q interpolates the Dirichlet values into the free pixels next
      // to them (what P cannot: its corrections fall to 0 towards a Dirichlet pixel), u_1 is
      // FMG's solution of the coarse problem for the rest, whose right-hand side is the residual
      // of q restricted, and so on down the levels.
      addDirichletExtension();
      restrictResidual(0, u_[0].data(), nullptr, f_[1].data());
      for (int l = 1; l < coarsest; ++l) {
        std::fill(u_[l].begin(), u_[l].end(), Px{});
        restrictResidual(l, u_[l].data(), f_[l].data(), f_[l + 1].data());
      }
      solveCoarsest(u_[coarsest].data(), f_[coarsest].data());
      for (int l = coarsest - 1; l >= 1; --l) {
        prolong<false>(l, u_[l + 1].data(), u_[l].data());
        for (int k = 0; k < options_.intermediate_cycles; ++k) {
          vcycle(l, u_[l].data(), f_[l].data());
        }
      }
      prolong<true>(0, u_[1].data(), u_[0].data());
    }
    FineProgress progress;
    conjugateGradients(progress);
    if (report) {
      report->levels = levelCount();
      report->fine_cycles = progress.iterations;
      report->converged = progress.converged;
      report->residuals = std::move(progress.residuals);
      report->error_estimates = std::move(progress.error_estimates);
      report->updates = std::move(progress.updates);
    }
    finestValues(values);
  }

 private:
  int levelCount() const { return static_cast<int>(coarse_.size()) + 1; }

  // Sizes `field` (keeping its storage) and zeroes its ghost border, which the smoothers and
  // residuals read with weight 0 (garbage there could be NaN).
  static void allocateField(size_t size, int stride, int height, Field& field) {
    if (field.size() != size) {
      field.clear();  // nothing to copy over when the storage grows
      field.resize(size);
    }
    const int s = stride, rows = height + 2;
    std::fill_n(field.begin(), s, Px{});
    std::fill_n(field.begin() + static_cast<long>(rows - 1) * s, s, Px{});
    for (int y = 1; y + 1 < rows; ++y) {
      field[static_cast<size_t>(y) * s] = Px{};
      field[static_cast<size_t>(y) * s + s - 1] = Px{};
    }
  }

  static float channel(const Px& value, int c) {
    if constexpr (C == 3) {
      return value[c];
    } else {
      return value;
    }
  }

  static void setChannel(Px& value, int c, float x) {
    if constexpr (C == 3) {
      value[c] = x;
    } else {
      value = x;
    }
  }

  static void accumulate(Sum& sum, const Px& value) {
    for (int c = 0; c < C; ++c) sum[c] += channel(value, c);
  }

  // num / den per channel; 0 where den is not positive (a channel already solved exactly).
  static Px ratio(const Sum& num, const Sum& den) {
    Px out{};
    for (int c = 0; c < C; ++c) {
      setChannel(out, c, den[c] > 0.0 ? static_cast<float>(num[c] / den[c]) : 0.0f);
    }
    return out;
  }

  static Px ratio(const Sum& num, double den) {
    Sum all;
    all.fill(den);
    return ratio(num, all);
  }

  // Root mean square over the finest level's free pixels and channels, from a per-channel sum
  // of squares.
  double rms(const Sum& squares) const {
    double total = 0.0;
    for (int c = 0; c < C; ++c) total += squares[c];
    return free_count_ ? std::sqrt(total / (static_cast<double>(free_count_) * C)) : 0.0;
  }

  // Sums term(p) over the free pixels of the finest level (per row in float, then in double).
  template <class Term>
  Sum sumOverFree(Term&& term) const {
    Sum total{};
    for (int y = 0; y < fine_.height; ++y) {
      Px row{};
      for (int p = fine_.index(0, y), end = fine_.index(fine_.width, y); p < end; ++p) {
        if (!(fine_.mask[p] & kFixed)) row += term(p);
      }
      accumulate(total, row);
    }
    return total;
  }

  // The largest magnitude over the free pixels and channels of a field of the finest level.
  double maxOverFree(const Px* __restrict v) const {
    Px largest{};
    for (size_t i = 0; i < fine_.size; ++i) {
      const Px magnitude = v[i] < 0 ? -v[i] : v[i];  // 0 at Dirichlet pixels and the border
      largest = magnitude > largest ? magnitude : largest;
    }
    double result = 0.0;
    for (int c = 0; c < C; ++c) result = std::max(result, static_cast<double>(channel(largest, c)));
    return result;
  }

  // The finest level's start: Dirichlet values, 0 at the free pixels (replaced by FMG's
  // interpolation when there are coarser levels).
  void setDirichletValues() {
    const GridProblem& problem = *problem_;
    for (int y = 0; y < fine_.height; ++y) {
      for (int x = 0; x < fine_.width; ++x) {
        const int q = y * fine_.width + x;
        Px& value = u_[0][fine_.index(x, y)];
        value = Px{};
        if (problem.fixed[q]) {
          for (int c = 0; c < C; ++c) setChannel(value, c, problem.values[q * C + c]);
        }
      }
    }
  }

  // Writes q (see solve) into the free pixels of u_[0], which are 0: P's interpolation rules
  // applied to the Dirichlet values alone. The x- and y-edge points of a cell first, from the
  // coarse-type and Dirichlet neighbours (a free neighbour across the collapsed direction
  // counts as the point itself, as in P), then its centre from the edge points around it. Where
  // the cell's weights are bilinear no Dirichlet pixel is linked: q is 0 there.
  void addDirichletExtension() {
    const CoarseLevel& coarse = coarse_[0];
    const Transfer& transfer = transfers_[0];
    Px* __restrict u = u_[0].data();
    const std::uint8_t* mask = fine_.mask.data();
    const int s = fine_.stride;
    const auto isBilinear = [](const CellWeights& w) {
      return w.x_west == 0.5f && w.x_east == 0.5f && w.y_north == 0.5f && w.y_south == 0.5f &&
             w.nw == 0.25f && w.ne == 0.25f && w.sw == 0.25f && w.se == 0.25f;
    };
    // Linked neighbours' values over the pixel's degree less its links to free pixels along
    // `collapsed` (kUp | kDown for an x-edge point, kLeft | kRight for a y-edge one, 0 for a
    // centre point).
    const auto extend = [&](int p, std::uint8_t collapsed) {
      const std::uint8_t m = mask[p];
      if (m & kFixed) return;
      Px sum{};
      float denominator = 0.0f;
      for (const auto& [link, q] :
           {std::pair{kLeft, p - 1}, {kRight, p + 1}, {kUp, p - s}, {kDown, p + s}}) {
        if (!(m & link)) continue;
        sum += u[q];
        if (!(link & collapsed) || (mask[q] & kFixed)) denominator += 1.0f;
      }
      if (denominator > 0.0f) u[p] = sum / denominator;
    };
    for (int pass = 0; pass < 2; ++pass) {
      for (int j = 0; j < coarse.height; ++j) {
        for (int i = 0; i < coarse.width; ++i) {
          if (isBilinear(transfer[coarse.index(i, j)])) continue;
          const int corner = fine_.index(2 * i, 2 * j);
          if (pass == 0) {
            if (2 * i + 1 < fine_.width) extend(corner + 1, kUp | kDown);
            if (2 * j + 1 < fine_.height) extend(corner + s, kLeft | kRight);
          } else if (2 * i + 1 < fine_.width && 2 * j + 1 < fine_.height) {
            extend(corner + s + 1, 0);
          }
        }
      }
    }
  }

  // Preconditioned conjugate gradients on the finest level from u_[0]; the preconditioner is
  // one V-cycle from zero on the residual.
  void conjugateGradients(FineProgress& progress) {
    const bool until_converged = options_.tolerance > 0.0;
    const bool record = options_.record_residuals || until_converged;
    const int iterations = until_converged ? options_.max_fine_cycles : options_.fine_cycles;
    const size_t size = fine_.size;
    Px* __restrict u = u_[0].data();
    Px* __restrict r = r_.data();
    Px* __restrict z = z_.data();
    Px* __restrict p = p_.data();
    Px* __restrict ap = ap_.data();
    for (size_t i = 0; i < size; ++i) r[i] = residualAt(fine_, u, nullptr, i);
    if (record) progress.residuals.push_back(residualNorm(r));
    Sum rz_previous{};
    for (int k = 0; k <= iterations; ++k) {
      const bool last = k == iterations;
      if (last && !until_converged) break;  // a fixed count needs no estimate of the result
      precondition(r, z);
      if (record) {
        // z = B r approximates the error of u (exactly if the V-cycle inverted A).
        const double estimate = maxOverFree(z);
        progress.error_estimates.push_back(estimate);
        progress.converged = until_converged && estimate <= options_.tolerance;
        if (progress.converged || last) {
          for (size_t i = 0; i < size; ++i) u[i] += z[i];  // the estimate's correction, for free
          break;
        }
      }
      const Sum rz = sumOverFree([&](int i) { return r[i] * z[i]; });
      const Px beta = k == 0 ? Px{} : ratio(rz, rz_previous);
      rz_previous = rz;
      // p stays 0 where z is (Dirichlet pixels, ghost border).
      if (k == 0) {
        std::copy_n(z, size, p);
      } else {
        for (size_t i = 0; i < size; ++i) p[i] = z[i] + beta * p[i];
      }
      const Sum pap = sumOverFree([&](int i) {
        ap[i] = -residualAt(fine_, p, nullptr, i);  // A p (p is 0 at Dirichlet pixels)
        return p[i] * ap[i];
      });
      const Px alpha = ratio(rz, pap);
      Sum update_squares{};
      const Sum rr = sumOverFree([&](int i) {
        const Px step = alpha * p[i];
        u[i] += step;
        r[i] -= alpha * ap[i];
        accumulate(update_squares, step * step);
        return r[i] * r[i];
      });
      ++progress.iterations;
      if (record) {
        progress.residuals.push_back(rms(rr));
        progress.updates.push_back(rms(update_squares));
      }
    }
  }

  // z = (I - Q A) B (I - A Q) r + Q r: the V-cycle B balanced by the components' constants.
  void precondition(const Px* __restrict r, Px* __restrict z) {
    const size_t size = fine_.size;
    if (!balance_) {
      std::fill_n(z, size, Px{});
      vcycle(0, z, r);
      return;
    }
    const FreeComponents& fc = components_;
    const size_t components = static_cast<size_t>(fc.count);
    Px* __restrict balanced = ap_.data();  // free here: CG recomputes it after
    pins_.assign(components, 0.0);
    sums_.assign(components, Sum{});
    for (const auto& pin : fc.pinned) pins_[fc.component[pin.pixel]] += pin.links;
    for (size_t i = 0; i < size; ++i) {
      if (fc.component[i] >= 0) accumulate(sums_[fc.component[i]], r[i]);
    }
    constant_.resize(components);
    for (size_t k = 0; k < components; ++k) constant_[k] = ratio(sums_[k], pins_[k]);
    std::copy_n(r, size, balanced);
    for (const auto& pin : fc.pinned) {
      balanced[pin.pixel] -= pin.links * constant_[fc.component[pin.pixel]];
    }
    std::fill_n(z, size, Px{});
    vcycle(0, z, balanced);
    sums_.assign(components, Sum{});
    for (const auto& pin : fc.pinned) {
      accumulate(sums_[fc.component[pin.pixel]], pin.links * z[pin.pixel]);
    }
    for (size_t k = 0; k < components; ++k) constant_[k] -= ratio(sums_[k], pins_[k]);
    for (size_t i = 0; i < size; ++i) {
      if (fc.component[i] >= 0) z[i] += constant_[fc.component[i]];
    }
  }

  void vcycle(int l, Px* u, const Px* f) {
    const int coarsest = levelCount() - 1;
    if (l == coarsest) {
      solveCoarsest(u, f);
      return;
    }
    smoothLevel(l, u, f, options_.pre_smoothing, false);
    restrictResidual(l, u, f, f_[l + 1].data());
    std::fill(u_[l + 1].begin(), u_[l + 1].end(), Px{});
    vcycle(l + 1, u_[l + 1].data(), f_[l + 1].data());
    prolong<true>(l, u_[l + 1].data(), u);
    smoothLevel(l, u, f, options_.post_smoothing, true);  // the adjoint of the pre-smoothing
  }

  void smoothLevel(int l, Px* u, const Px* f, int sweeps, bool reverse) const {
    if (l == 0) {
      smoothFine(u, f, sweeps, reverse);
    } else {
      smoothCoarse(coarse_[l - 1], u, f, sweeps, reverse);
    }
  }

  // Red-black Gauss-Seidel on the free pixels of the finest level: u_p = (f_p + sum w u_q) /
  // sum w, red pixels (x + y even) first, or black first if `black_first`. The second
  // half-sweep trails the first by a row, so one pass over memory does a full sweep.
  void smoothFine(Px* u, const Px* f, int sweeps, bool black_first) const {
    const int order = black_first ? 1 : 0;
    for (int sweep = 0; sweep < sweeps; ++sweep) {
      for (int y = 0; y <= fine_.height; ++y) {
        const int first_x = (y + order) & 1;  // leading row y, trailing row y - 1: other colour
        if (f) {
          if (y < fine_.height) relaxRow<true>(u, f, y, first_x);
          if (y > 0) relaxRow<true>(u, f, y - 1, first_x);
        } else {
          if (y < fine_.height) relaxRow<false>(u, f, y, first_x);
          if (y > 0) relaxRow<false>(u, f, y - 1, first_x);
        }
      }
    }
  }

  // Relaxes the pixels x = first_x, first_x + 2, ... of row y of the finest level.
  template <bool kHasRhs>
  void relaxRow(Px* __restrict u, const Px* __restrict f, int y, int first_x) const {
    const int s = fine_.stride;
    const std::uint8_t* __restrict mask = fine_.mask.data();
    for (int p = fine_.index(first_x, y), end = fine_.index(fine_.width, y); p < end; p += 2) {
      const std::uint8_t m = mask[p];
      if (m == kAllLinks) {  // the common case: an interior pixel away from curves
        Px sum = u[p - 1] + u[p + 1] + u[p - s] + u[p + s];
        if constexpr (kHasRhs) sum += f[p];
        u[p] = sum * 0.25f;
      } else if (!(m & kFixed)) {
        const LinkWeights& w = kWeights[m];
        Px sum = w.left * u[p - 1] + w.right * u[p + 1] + w.up * u[p - s] + w.down * u[p + s];
        if constexpr (kHasRhs) sum += f[p];
        u[p] = sum * w.inv_degree;
      }
    }
  }

  // Lexicographic Gauss-Seidel on a coarse level, forwards or (the adjoint) backwards. Points
  // that are not unknowns have zero rows and stay 0.
  static void smoothCoarse(const CoarseLevel& level, Px* __restrict u, const Px* __restrict f,
                           int sweeps, bool backwards) {
    for (int sweep = 0; sweep < sweeps; ++sweep) {
      for (int row = 0; row < level.height; ++row) {
        const int y = backwards ? level.height - 1 - row : row;
        if (backwards) {
          for (int p = level.index(level.width - 1, y), end = level.index(0, y); p >= end; --p) {
            u[p] = (f[p] - offDiagonal(level, u, p)) * level.inverse_centre[p];
          }
        } else {
          for (int p = level.index(0, y), end = level.index(level.width, y); p < end; ++p) {
            u[p] = (f[p] - offDiagonal(level, u, p)) * level.inverse_centre[p];
          }
        }
      }
    }
  }

  // The off-diagonal part of a coarse row times u.
  static Px offDiagonal(const CoarseLevel& level, const Px* __restrict u, int p) {
    const int s = level.stride;
    return level.east[p] * u[p + 1] + level.east[p - 1] * u[p - 1] + level.south[p] * u[p + s] +
           level.south[p - s] * u[p - s] + level.south_east[p] * u[p + s + 1] +
           level.south_east[p - s - 1] * u[p - s - 1] + level.south_west[p] * u[p + s - 1] +
           level.south_west[p - s + 1] * u[p - s + 1];
  }

  // The residual f - A u at pixel p of the finest level; without f, u holds the Dirichlet
  // values (the right-hand side). 0 at Dirichlet pixels and in the ghost border. Summed as
  // differences of neighbouring values, which are exact in floating point where the values are
  // close (a sum of four values less 4 u loses ~1e-7 absolute per pixel, which in a region
  // pinned by a few pixels adds up to errors of 1e-4 in the solution).
  static Px residualAt(const FineLevel& level, const Px* __restrict u, const Px* __restrict f,
                       size_t p) {
    const size_t s = static_cast<size_t>(level.stride);
    const std::uint8_t m = level.mask[p];
    Px r;
    if (m == kAllLinks) {
      const Px centre = u[p];
      r = ((u[p - 1] - centre) + (u[p + 1] - centre)) + ((u[p - s] - centre) + (u[p + s] - centre));
    } else if (m & kFixed) {
      return Px{};
    } else {
      const LinkWeights& w = kWeights[m];
      r = w.left * (u[p - 1] - u[p]) + w.right * (u[p + 1] - u[p]) + w.up * (u[p - s] - u[p]) +
          w.down * (u[p + s] - u[p]);
    }
    return f ? r + f[p] : r;
  }

  static Px residualAt(const CoarseLevel& level, const Px* __restrict u, const Px* __restrict f,
                       size_t p) {
    const int q = static_cast<int>(p);
    return f[q] - level.centre[q] * u[q] - offDiagonal(level, u, q);
  }

  // RMS of a residual field of the finest level (0 at Dirichlet pixels).
  double residualNorm(const Px* r) const {
    return rms(sumOverFree([&](int i) { return r[i] * r[i]; }));
  }

  // Restricts the residual of level l to level l + 1 with P^T: each fine point sends its
  // residual to the coarse points its correction comes from, with the same weights.
  void restrictResidual(int l, const Px* u, const Px* f, Px* fc) const {
    if (l == 0) {
      restrictFrom(fine_, l, u, f, fc);
    } else {
      restrictFrom(coarse_[l - 1], l, u, f, fc);
    }
  }

  template <class Op>
  void restrictFrom(const Op& fine, int l, const Px* __restrict u, const Px* __restrict f,
                    Px* __restrict fc) const {
    const CoarseLevel& coarse = coarse_[l];
    const Transfer& transfer = transfers_[l];
    const int fs = fine.stride, cs = coarse.stride;
    std::fill_n(fc, coarse.size, Px{});
    for (int j = 0; j < coarse.height; ++j) {
      for (int i = 0; i < coarse.width; ++i) {
        const int c = coarse.index(i, j);
        const size_t p = static_cast<size_t>(fine.index(2 * i, 2 * j));
        const CellWeights& w = transfer[c];
        // The x-edge and y-edge points (and so the centre) of the last cells can lie outside.
        const bool x_inside = 2 * i + 1 < fine.width, y_inside = 2 * j + 1 < fine.height;
        const Px r00 = residualAt(fine, u, f, p);
        const Px r10 = x_inside ? residualAt(fine, u, f, p + 1) : Px{};
        const Px r01 = y_inside ? residualAt(fine, u, f, p + fs) : Px{};
        const Px r11 = x_inside && y_inside ? residualAt(fine, u, f, p + fs + 1) : Px{};
        fc[c] += r00 + w.x_west * r10 + w.y_north * r01 + w.nw * r11;
        fc[c + 1] += w.x_east * r10 + w.ne * r11;
        fc[c + cs] += w.y_south * r01 + w.sw * r11;
        fc[c + cs + 1] += w.se * r11;
      }
    }
  }

  // P times the coarse field: added to u (a correction) or, for FMG, assigned to the free
  // points of level l (the interpolated solution).
  template <bool kAdd>
  void prolong(int l, const Px* __restrict coarse_values, Px* __restrict u) const {
    const CoarseLevel& coarse = coarse_[l];
    const Transfer& transfer = transfers_[l];
    const int fs = l == 0 ? fine_.stride : coarse_[l - 1].stride;
    const int cs = coarse.stride;
    const auto store = [&](size_t p, const Px& value) {
      if constexpr (kAdd) {
        u[p] += value;
      } else if (l > 0 || !(fine_.mask[p] & kFixed)) {
        u[p] = value;
      }
    };
    for (int j = 0; j < coarse.height; ++j) {
      for (int i = 0; i < coarse.width; ++i) {
        const int c = coarse.index(i, j);
        const size_t p = static_cast<size_t>((2 * j + 1) * fs + 2 * i + 1);
        const CellWeights& w = transfer[c];
        const Px a = coarse_values[c], b = coarse_values[c + 1];
        const Px d = coarse_values[c + cs], e = coarse_values[c + cs + 1];
        store(p, a);
        store(p + 1, w.x_west * a + w.x_east * b);
        store(p + fs, w.y_north * a + w.y_south * d);
        store(p + fs + 1, w.nw * a + w.ne * b + w.sw * d + w.se * e);
      }
    }
  }

  template <class Op>
  void factoriseCoarsest(const Op& level) {
    const int w = level.width, n = level.width * level.height;
    coarsest_.reset(n, w + 1);
    for (int k = 0; k < n; ++k) {
      const Stencil a = level.row(level.index(k % w, k / w));
      if (a[kC] == 0.0f) {  // not an unknown: an identity row keeps it at 0
        coarsest_.lower(k, k) = 1.0;
        continue;
      }
      coarsest_.lower(k, k) = a[kC];
      if (k % w > 0) coarsest_.lower(k, k - 1) = a[kW];
      if (k >= w) {
        coarsest_.lower(k, k - w) = a[kN];
        if (k % w > 0) coarsest_.lower(k, k - w - 1) = a[kNW];
        if (k % w + 1 < w) coarsest_.lower(k, k - w + 1) = a[kNE];
      }
    }
    coarsest_.factorise();
    coarsest_values_.resize(n);
  }

  // Solves the coarsest level exactly, per channel.
  void solveCoarsest(Px* u, const Px* f) {
    const int l = levelCount() - 1;
    const int w = l == 0 ? fine_.width : coarse_[l - 1].width;
    const int stride = w + 2;
    const int n = coarsest_.size();
    for (int c = 0; c < C; ++c) {
      for (int k = 0; k < n; ++k) {
        coarsest_values_[k] = channel(f[(k / w + 1) * stride + k % w + 1], c);
      }
      coarsest_.solve(coarsest_values_.data());
      for (int k = 0; k < n; ++k) {
        const int p = (k / w + 1) * stride + k % w + 1;
        const bool unknown = l == 0 ? fine_.isFree(p) : coarse_[l - 1].isFree(p);
        // Level 0 as the coarsest: its Dirichlet pixels keep their values.
        if (unknown) {
          setChannel(u[p], c, static_cast<float>(coarsest_values_[k]));
        } else if (l > 0) {
          setChannel(u[p], c, 0.0f);
        }
      }
    }
  }

  void finestValues(float* out) const {
    for (int y = 0; y < fine_.height; ++y) {
      for (int x = 0; x < fine_.width; ++x) {
        const Px& value = u_[0][fine_.index(x, y)];
        for (int c = 0; c < C; ++c) *out++ = channel(value, c);
      }
    }
  }

  const GridProblem* problem_ = nullptr;
  MultigridOptions options_;
  FineLevel fine_;
  std::vector<CoarseLevel> coarse_;  // level l + 1 at index l
  std::vector<Transfer> transfers_;  // from level l + 1 to level l at index l
  std::vector<std::uint8_t> flags_;  // coarsening scratch
  BandedCholesky coarsest_;
  std::vector<double> coarsest_values_;
  size_t free_count_ = 0;
  std::vector<Field> u_, f_;  // per level: solution (FMG) or correction (V-cycle), rhs
  Field r_, z_, p_, ap_;      // CG: residual, preconditioned residual, direction, A direction
  bool balance_ = getenv("VICC_BALANCE") != nullptr;
  FreeComponents components_;
  std::vector<double> pins_;
  std::vector<Sum> sums_;
  std::vector<Px> constant_;
};

}  // namespace
}  // namespace multigrid_detail

std::vector<std::pair<int, int>> levelSizes(int width, int height, int coarsest_size) {
  std::vector<std::pair<int, int>> sizes{{width, height}};
  const int target = std::max(coarsest_size, 1);
  while (std::max(width, height) > target) {
    width = (width + 1) / 2;
    height = (height + 1) / 2;
    sizes.emplace_back(width, height);
  }
  return sizes;
}

struct MultigridSolver::Workspaces {
  multigrid_detail::Multigrid<3> color;
  multigrid_detail::Multigrid<1> single;
};

MultigridSolver::MultigridSolver() : workspaces_(std::make_unique<Workspaces>()) {}
MultigridSolver::~MultigridSolver() = default;

void MultigridSolver::solve(const GridProblem& problem, const MultigridOptions& options,
                            std::vector<float>& values, MultigridReport* report) {
  // Bad input is reported by the other overload; only a valid problem sizes `values`.
  if (problem.width > 0 && problem.height > 0 && problem.channels > 0) {
    values.resize(static_cast<size_t>(problem.pixelCount()) * problem.channels);
  }
  solve(problem, options, values.data(), report);
}

namespace {

void validate(const GridProblem& problem, const MultigridOptions& options) {
  if (problem.width <= 0 || problem.height <= 0) {
    throw std::invalid_argument("solveMultigrid: empty grid");
  }
  if (problem.channels != 1 && problem.channels != 3) {
    throw std::invalid_argument("solveMultigrid: only 1 or 3 channels are supported, got " +
                                std::to_string(problem.channels));
  }
  const size_t n = static_cast<size_t>(problem.pixelCount());
  if (problem.couples_right.size() != n || problem.couples_down.size() != n ||
      problem.fixed.size() != n || problem.values.size() != n * problem.channels) {
    throw std::invalid_argument("solveMultigrid: the problem's arrays do not match its " +
                                std::to_string(problem.width) + " x " +
                                std::to_string(problem.height) + " grid");
  }
  if (options.coarsest_size < 1 || options.coarsest_size > MultigridOptions::kMaxCoarsestSize) {
    throw std::invalid_argument("solveMultigrid: coarsest_size must be 1.." +
                                std::to_string(MultigridOptions::kMaxCoarsestSize) + ", got " +
                                std::to_string(options.coarsest_size));
  }
  if (options.pre_smoothing < 0 || options.post_smoothing < 0 || options.intermediate_cycles < 0 ||
      options.max_fine_cycles < 0 || options.fine_cycles < 0 || !(options.tolerance >= 0.0)) {
    throw std::invalid_argument("solveMultigrid: negative counts or tolerance");
  }
}

}  // namespace

void MultigridSolver::solve(const GridProblem& problem, const MultigridOptions& options,
                            float* values, MultigridReport* report) {
  validate(problem, options);
  if (problem.channels == 3) {
    workspaces_->color.prepare(problem, options);
    workspaces_->color.solve(values, report);
  } else {
    workspaces_->single.prepare(problem, options);
    workspaces_->single.solve(values, report);
  }
}

std::vector<float> solveMultigrid(const GridProblem& problem, const MultigridOptions& options,
                                  MultigridReport* report) {
  std::vector<float> values;
  MultigridSolver().solve(problem, options, values, report);
  return values;
}

}  // namespace vicc_glyphs
