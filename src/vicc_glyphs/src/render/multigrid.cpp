#include "vicc_glyphs/render/multigrid.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <type_traits>
#include <utility>

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
  // Sets up the levels for `problems`, reusing the memory of the previous solve.
  void prepare(const std::vector<GridProblem>& problems, const MultigridOptions& options) {
    problems_ = &problems;
    options_ = options;
    const size_t count = problems.size();
    levels_.resize(count);
    free_counts_.resize(count);
    u_.resize(count);
    f_.resize(count);
    // Fields are not zero-filled (fresh memory would be touched twice): every interior value
    // is written before it is read, and only the ghost borders need zeros.
    for (size_t l = 0; l < count; ++l) {
      makeLevel(problems[l], levels_[l]);
      free_counts_[l] =
          static_cast<size_t>(std::count_if(problems[l].fixed.begin(), problems[l].fixed.end(),
                                            [](std::uint8_t fixed) { return !fixed; }));
      allocateField(levels_[l], u_[l]);
      if (l + 1 < count) labelFreeComponents(levels_[l]);  // the levels the CG runs on
      if (l > 0) allocateField(levels_[l], f_[l]);  // the finest level has no right-hand side
    }
    if (count > 1) {  // sized for the finest level, used on every level the CG runs on
      for (Field* field : {&r_, &z_, &p_, &ap_, &balanced_}) allocateField(levels_[0], *field);
    }
    for (size_t l = 0; l + 1 < levels_.size(); ++l) {
      Level& fine = levels_[l];
      const Level& coarse = levels_[l + 1];
      prolongationTable(fine.width, coarse.width, fine.coarse_x, fine.coarse_x_neighbour);
      prolongationTable(fine.height, coarse.height, fine.coarse_y, fine.coarse_y_neighbour);
      prolongationSources(fine, coarse);
    }
  }

  // FMG: the coarsest problem is smoothed to convergence; on every finer level the coarser
  // solution, interpolated, starts a conjugate-gradient solve preconditioned by one V-cycle.
  void solve(float* values, MultigridReport* report) {
    const int coarsest = static_cast<int>(levels_.size()) - 1;
    FineProgress progress;
    setDirichletValues(coarsest);
    smoothSymmetric(coarsest, u_[coarsest].data(), nullptr, options_.coarsest_sweeps);
    for (int l = coarsest - 1; l >= 0; --l) {
      setDirichletValues(l);
      prolong<false>(l, u_[l + 1].data(), u_[l].data());
      conjugateGradients(l, progress);
    }
    if (coarsest == 0 && options_.record_residuals) progress.residuals.push_back(residualNorm(0));
    if (report) {
      report->levels = static_cast<int>(levels_.size());
      report->fine_cycles = progress.iterations;
      report->converged = progress.converged;
      report->residuals = std::move(progress.residuals);
      report->error_estimates = std::move(progress.error_estimates);
      report->updates = std::move(progress.updates);
    }
    finestValues(values);
  }

 private:
  // Sizes `field` for `level` (keeping its storage) and zeroes its ghost border, which the
  // smoother and the residual read with weight 0 (garbage there could be NaN).
  static void allocateField(const Level& level, Field& field) {
    if (field.size() != level.size) {
      field.clear();  // nothing to copy over when the storage grows
      field.resize(level.size);
    }
    const int s = level.stride, rows = level.height + 2;
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

  // Root mean square over the free pixels and channels of level l, from a per-channel sum of
  // squares.
  double rms(int l, const Sum& squares) const {
    double total = 0.0;
    for (int c = 0; c < C; ++c) total += squares[c];
    const size_t free = free_counts_[l];
    return free ? std::sqrt(total / (static_cast<double>(free) * C)) : 0.0;
  }

  // Sums term(p) over the free pixels of level l (per row in float, then in double).
  template <class Term>
  Sum sumOverFree(int l, Term&& term) const {
    const Level& level = levels_[l];
    Sum total{};
    for (int y = 0; y < level.height; ++y) {
      Px row{};
      for (int p = level.index(0, y), end = level.index(level.width, y); p < end; ++p) {
        if (!(level.mask[p] & kFixed)) row += term(p);
      }
      accumulate(total, row);
    }
    return total;
  }

  // The largest magnitude over the free pixels and channels of a field of level l.
  double maxOverFree(int l, const Px* __restrict v) const {
    const Level& level = levels_[l];
    Px largest{};
    for (size_t i = 0; i < level.size; ++i) {
      const Px magnitude = v[i] < 0 ? -v[i] : v[i];  // 0 at Dirichlet pixels and the border
      largest = magnitude > largest ? magnitude : largest;
    }
    double result = 0.0;
    for (int c = 0; c < C; ++c) result = std::max(result, static_cast<double>(channel(largest, c)));
    return result;
  }

  // Initialises level l for FMG: Dirichlet values, and 0 at the free pixels of the coarsest
  // level (finer levels get theirs by interpolation right after).
  void setDirichletValues(int l) {
    const GridProblem& problem = (*problems_)[l];
    const Level& level = levels_[l];
    const bool coarsest = l + 1 == static_cast<int>(levels_.size());
    for (int y = 0; y < level.height; ++y) {
      for (int x = 0; x < level.width; ++x) {
        const int q = y * level.width + x;
        Px& value = u_[l][level.index(x, y)];
        if (problem.fixed[q]) {
          for (int c = 0; c < C; ++c) setChannel(value, c, problem.values[q * C + c]);
        } else if (coarsest) {
          value = Px{};
        }
      }
    }
  }

  // Preconditioned conjugate gradients on level l, from the interpolated start in u_[l]; the
  // preconditioner is one V-cycle from zero on the residual, balanced (see precondition). The
  // coarse problems are re-rasterised, not Galerkin products, so a region coupled to its Dirichlet
  // pixels only through gaps between barriers can be coupled many times more weakly (or strongly)
  // on a coarse grid: as a stationary iteration the V-cycle then overshoots and diverges (or
  // stalls). As a preconditioner it stays symmetric positive definite (symmetric smoothing,
  // restriction = transposed prolongation, SPD coarse problems), and CG removes the few
  // badly scaled error components those regions add in about as many iterations.
  void conjugateGradients(int l, FineProgress& progress) {
    const bool finest = l == 0;
    const bool until_converged = finest && options_.tolerance > 0.0;
    const bool record = finest && (options_.record_residuals || until_converged);
    const int iterations = until_converged ? options_.max_fine_cycles
                           : finest        ? options_.fine_cycles
                                           : options_.intermediate_cycles;
    const Level& level = levels_[l];
    Px* __restrict u = u_[l].data();
    Px* __restrict r = r_.data();
    Px* __restrict z = z_.data();
    Px* __restrict p = p_.data();
    Px* __restrict ap = ap_.data();
    // Over the whole layout: the buffers are sized for the finest level, and this level's
    // ghost border and Dirichlet pixels must read 0 in r, z and p.
    for (size_t i = 0; i < level.size; ++i) r[i] = residualAt(level, u, nullptr, i);
    if (record) progress.residuals.push_back(residualNorm(l, r));
    Sum rz_previous{};
    for (int k = 0; k < iterations; ++k) {
      precondition(l, r, z);
      const Sum rz = sumOverFree(l, [&](int i) { return r[i] * z[i]; });
      if (record) {
        // z = B r approximates the error of u (exactly if the V-cycle inverted A).
        const double estimate = maxOverFree(l, z);
        progress.error_estimates.push_back(estimate);
        if (until_converged && estimate <= options_.tolerance) {
          progress.converged = true;
          break;
        }
      }
      const Px beta = k == 0 ? Px{} : ratio(rz, rz_previous);
      rz_previous = rz;
      // p stays 0 where z is (Dirichlet pixels, ghost border); at k = 0 p_ holds another
      // level's layout.
      if (k == 0) {
        std::copy_n(z, level.size, p);
      } else {
        for (size_t i = 0; i < level.size; ++i) p[i] = z[i] + beta * p[i];
      }
      const Sum pap = sumOverFree(l, [&](int i) {
        ap[i] = -residualAt(level, p, nullptr, i);  // A p (p is 0 at Dirichlet pixels)
        return p[i] * ap[i];
      });
      const Px alpha = ratio(rz, pap);
      Sum update_squares{};
      const Sum rr = sumOverFree(l, [&](int i) {
        const Px step = alpha * p[i];
        u[i] += step;
        r[i] -= alpha * ap[i];
        accumulate(update_squares, step * step);
        return r[i] * r[i];
      });
      if (finest) ++progress.iterations;
      if (record) {
        progress.residuals.push_back(rms(l, rr));
        progress.updates.push_back(rms(l, update_squares));
      }
    }
  }

  // z = (I - Q A) B (I - A Q) r + Q r: the V-cycle B balanced by the coarse space of the free
  // components' constants (Mandel's balancing; Nicolaides' deflation), Q = W (W^T A W)^-1 W^T
  // with W the components' indicator vectors. A region that reaches its Dirichlet pixels only
  // through a few gaps is nearly singular: its constant mode is pinned by those few links and
  // every coarse grid pins it differently, so the V-cycle corrects it by a wrong factor; Q
  // corrects it exactly. Components are not linked, so W^T A W is diagonal, and as A's
  // internal links cancel in a component's sum, W^T A v is the sum of pin links * v over the
  // pinned pixels. Symmetric positive definite whenever B is.
  void precondition(int l, const Px* __restrict r, Px* __restrict z) {
    const Level& level = levels_[l];
    const size_t components = static_cast<size_t>(level.component_count);
    Px* __restrict balanced = balanced_.data();
    pins_.assign(components, 0.0);
    sums_.assign(components, Sum{});
    for (const Level::Pinned& pin : level.pinned) pins_[level.component[pin.pixel]] += pin.links;
    for (size_t i = 0; i < level.size; ++i) {
      if (level.component[i] >= 0) accumulate(sums_[level.component[i]], r[i]);
    }
    constant_.resize(components);  // Q r per component
    for (size_t k = 0; k < components; ++k) constant_[k] = ratio(sums_[k], pins_[k]);
    std::copy_n(r, level.size, balanced);
    for (const Level::Pinned& pin : level.pinned) {
      balanced[pin.pixel] -= pin.links * constant_[level.component[pin.pixel]];  // - A Q r
    }
    std::fill_n(z, level.size, Px{});
    vcycle(l, z, balanced);
    sums_.assign(components, Sum{});
    for (const Level::Pinned& pin : level.pinned) {
      accumulate(sums_[level.component[pin.pixel]], pin.links * z[pin.pixel]);  // W^T A z
    }
    for (size_t k = 0; k < components; ++k) constant_[k] -= ratio(sums_[k], pins_[k]);
    for (size_t i = 0; i < level.size; ++i) {
      if (level.component[i] >= 0) z[i] += constant_[level.component[i]];
    }
  }

  void vcycle(int l, Px* u, const Px* f) {
    const int coarsest = static_cast<int>(levels_.size()) - 1;
    if (l == coarsest) {
      smoothSymmetric(l, u, f, options_.coarsest_sweeps);
      return;
    }
    smooth(l, u, f, options_.pre_smoothing, false);
    restrictResidual(l, u, f, f_[l + 1].data());
    std::fill(u_[l + 1].begin(), u_[l + 1].end(), Px{});
    vcycle(l + 1, u_[l + 1].data(), f_[l + 1].data());
    prolong<true>(l, u_[l + 1].data(), u);
    smooth(l, u, f, options_.post_smoothing, true);  // the adjoint of the pre-smoothing
  }

  // Sweeps alternating red-black and black-red order: an even count is a symmetric operator.
  void smoothSymmetric(int l, Px* u, const Px* f, int sweeps) const {
    for (int sweep = 0; sweep < sweeps; ++sweep) smooth(l, u, f, 1, sweep % 2 == 1);
  }

  // Red-black Gauss-Seidel on the free pixels: u_p = (f_p + sum w u_q) / sum w, red pixels
  // (x + y even) first, or black first if `black_first`. The second half-sweep trails the
  // first by a row, so one pass over memory does a full sweep.
  void smooth(int l, Px* u, const Px* f, int sweeps, bool black_first) const {
    const Level& level = levels_[l];
    const int order = black_first ? 1 : 0;
    for (int sweep = 0; sweep < sweeps; ++sweep) {
      for (int y = 0; y <= level.height; ++y) {
        const int first_x = (y + order) & 1;  // leading row y, trailing row y - 1: other colour
        if (f) {
          if (y < level.height) relaxRow<true>(level, u, f, y, first_x);
          if (y > 0) relaxRow<true>(level, u, f, y - 1, first_x);
        } else {
          if (y < level.height) relaxRow<false>(level, u, f, y, first_x);
          if (y > 0) relaxRow<false>(level, u, f, y - 1, first_x);
        }
      }
    }
  }

  // Relaxes the pixels x = first_x, first_x + 2, ... of row y.
  template <bool kHasRhs>
  static void relaxRow(const Level& level, Px* __restrict u, const Px* __restrict f, int y,
                       int first_x) {
    const int s = level.stride;
    const std::uint8_t* __restrict mask = level.mask.data();
    for (int p = level.index(first_x, y), end = level.index(level.width, y); p < end; p += 2) {
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

  // The residual f - A u at pixel p: 0 at Dirichlet pixels and in the ghost border.
  static Px residualAt(const Level& level, const Px* __restrict u, const Px* __restrict f,
                       size_t p) {
    const size_t s = static_cast<size_t>(level.stride);
    const std::uint8_t m = level.mask[p];
    Px r;
    if (m == kAllLinks) {
      r = u[p - 1] + u[p + 1] + u[p - s] + u[p + s] - 4.0f * u[p];
    } else if (m & kFixed) {
      return Px{};
    } else {
      const LinkWeights& w = kWeights[m];
      r = w.left * (u[p - 1] - u[p]) + w.right * (u[p + 1] - u[p]) + w.up * (u[p - s] - u[p]) +
          w.down * (u[p + s] - u[p]);
    }
    return f ? r + f[p] : r;
  }

  // RMS of a residual field of level l (0 at Dirichlet pixels) or, without one, of u's.
  double residualNorm(int l, const Px* r = nullptr) const {
    const Level& level = levels_[l];
    const Px* u = u_[l].data();
    return rms(l, sumOverFree(l, [&](int i) {
                 const Px value = r ? r[i] : residualAt(level, u, nullptr, i);
                 return value * value;
               }));
  }

  // Restricts the residual of level l to level l + 1 with the transpose of the correction
  // prolongation (same sources, same weights), which keeps the V-cycle symmetric: each fine
  // pixel sends its residual to the coarse cells its correction comes from, so a free pixel
  // in a Dirichlet coarse cell sends it to the free neighbours instead of losing it (next to
  // a curve that residual carries the smooth error of a whole region). The unscaled coarse
  // Laplacian matches this transpose's weights (4 per coarse cell); a grid side of 1 pixel
  // is not coarsened and gives half of them, so its factor 2 is applied explicitly.
  void restrictResidual(int l, const Px* __restrict u, const Px* __restrict f,
                        Px* __restrict fc) const {
    const Level& fine = levels_[l];
    const Level& coarse = levels_[l + 1];
    const float scale = (fine.width == 1 ? 2.0f : 1.0f) * (fine.height == 1 ? 2.0f : 1.0f);
    std::fill_n(fc, coarse.size, Px{});
    for (int y = 0; y < fine.height; ++y) {
      const int cy = fine.coarse_y[y], ny = fine.coarse_y_neighbour[y];
      const int p0 = fine.index(0, y);
      for (int x = 0; x < fine.width; ++x) {
        const std::uint8_t sources = fine.correction_sources[p0 + x];
        if (sources == kNoSources) continue;
        const int cx = fine.coarse_x[x], nx = fine.coarse_x_neighbour[x];
        const ProlongationWeights& w = kProlongation[sources];
        const Px r = scale * residualAt(fine, u, f, static_cast<size_t>(p0 + x));
        fc[coarse.index(cx, cy)] += w.near * r;
        fc[coarse.index(nx, cy)] += w.x * r;
        fc[coarse.index(cx, ny)] += w.y * r;
        fc[coarse.index(nx, ny)] += w.xy * r;
      }
    }
  }

  // Bilinear interpolation of the coarse field to the fine free pixels: added as a
  // correction (V-cycle) or assigned as the initial guess (FMG), with the sources each pixel
  // may use (see prolongationSources). kProlongation entries with no source are all zero.
  template <bool kAdd>
  void prolong(int l, const Px* __restrict coarse_values, Px* __restrict u) const {
    const Level& fine = levels_[l];
    const Level& coarse = levels_[l + 1];
    const std::uint8_t* all_sources =
        kAdd ? fine.correction_sources.data() : fine.solution_sources.data();
    for (int y = 0; y < fine.height; ++y) {
      const int cy = fine.coarse_y[y], ny = fine.coarse_y_neighbour[y];
      const int p0 = fine.index(0, y);
      for (int x = 0; x < fine.width; ++x) {
        const std::uint8_t sources = all_sources[p0 + x];
        if (sources == kNoSources) continue;
        const int cx = fine.coarse_x[x], nx = fine.coarse_x_neighbour[x];
        const ProlongationWeights& w = kProlongation[sources];
        const Px value = w.near * coarse_values[coarse.index(cx, cy)] +
                         w.x * coarse_values[coarse.index(nx, cy)] +
                         w.y * coarse_values[coarse.index(cx, ny)] +
                         w.xy * coarse_values[coarse.index(nx, ny)];
        if constexpr (kAdd) {
          u[p0 + x] += value;
        } else {
          u[p0 + x] = value;
        }
      }
    }
  }

  void finestValues(float* out) const {
    const Level& level = levels_[0];
    for (int y = 0; y < level.height; ++y) {
      for (int x = 0; x < level.width; ++x) {
        const Px& value = u_[0][level.index(x, y)];
        for (int c = 0; c < C; ++c) *out++ = channel(value, c);
      }
    }
  }

  const std::vector<GridProblem>* problems_ = nullptr;
  MultigridOptions options_;
  std::vector<Level> levels_;
  std::vector<size_t> free_counts_;
  std::vector<Field> u_, f_;  // per level: solution (FMG) or correction (V-cycle), rhs
  Field r_, z_, p_, ap_;      // CG: residual, preconditioned residual, direction, A direction
  Field balanced_;            // precondition: the residual with the components' constants removed
  std::vector<double> pins_;  // precondition, per component: W^T A W
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

void assembleLevels(
    int width, int height, int coarsest_size,
    const std::function<void(int width, int height, double scale, GridProblem& level)>& assemble,
    std::vector<GridProblem>& levels) {
  const std::vector<std::pair<int, int>> sizes = levelSizes(width, height, coarsest_size);
  levels.resize(sizes.size());
  double scale = 1.0;
  for (size_t l = 0; l < sizes.size(); ++l) {
    assemble(sizes[l].first, sizes[l].second, scale, levels[l]);
    scale *= 0.5;
  }
}

struct MultigridSolver::Workspaces {
  multigrid_detail::Multigrid<3> color;
  multigrid_detail::Multigrid<1> single;
};

MultigridSolver::MultigridSolver() : workspaces_(std::make_unique<Workspaces>()) {}
MultigridSolver::~MultigridSolver() = default;

void MultigridSolver::solve(const std::vector<GridProblem>& levels, const MultigridOptions& options,
                            std::vector<float>& values, MultigridReport* report) {
  // Bad input is reported by the other overload; only a valid finest level sizes `values`.
  if (!levels.empty() && levels.front().width > 0 && levels.front().height > 0 &&
      levels.front().channels > 0) {
    values.resize(static_cast<size_t>(levels.front().pixelCount()) * levels.front().channels);
  }
  solve(levels, options, values.data(), report);
}

void MultigridSolver::solve(const std::vector<GridProblem>& levels, const MultigridOptions& options,
                            float* values, MultigridReport* report) {
  if (levels.empty()) throw std::invalid_argument("solveMultigrid: no levels");
  const int channels = levels.front().channels;
  for (size_t l = 0; l < levels.size(); ++l) {
    const GridProblem& level = levels[l];
    if (level.channels != channels || level.width <= 0 || level.height <= 0) {
      throw std::invalid_argument("solveMultigrid: level " + std::to_string(l) +
                                  " is empty or has a different channel count");
    }
    if (l > 0 && (level.width != (levels[l - 1].width + 1) / 2 ||
                  level.height != (levels[l - 1].height + 1) / 2)) {
      throw std::invalid_argument("solveMultigrid: level " + std::to_string(l) +
                                  " is not half the size of the level above");
    }
  }
  if (channels == 3) {
    workspaces_->color.prepare(levels, options);
    workspaces_->color.solve(values, report);
  } else if (channels == 1) {
    workspaces_->single.prepare(levels, options);
    workspaces_->single.solve(values, report);
  } else {
    throw std::invalid_argument("solveMultigrid: only 1 or 3 channels are supported");
  }
}

std::vector<float> solveMultigrid(const std::vector<GridProblem>& levels,
                                  const MultigridOptions& options, MultigridReport* report) {
  std::vector<float> values;
  MultigridSolver().solve(levels, options, values, report);
  return values;
}

}  // namespace vicc_glyphs
