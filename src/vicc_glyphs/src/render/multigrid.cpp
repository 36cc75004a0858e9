#include "vicc_glyphs/render/multigrid.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <tuple>
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

template <int C>
class Multigrid {
  using Px = PixelValue<C>;
  using Field = render_detail::PixelVector<Px>;

 public:
  // Sets up the levels for `problems`, reusing the memory of the previous solve.
  void prepare(const std::vector<GridProblem>& problems, const MultigridOptions& options) {
    problems_ = &problems;
    options_ = options;
    const size_t count = problems.size();
    levels_.resize(count);
    u_.resize(count);
    f_.resize(count);
    e_.resize(count);
    // Fields are not zero-filled (fresh memory would be touched twice): every interior value
    // is written before it is read, and only the ghost borders need zeros.
    for (size_t l = 0; l < count; ++l) {
      makeLevel(problems[l], levels_[l]);
      allocateField(levels_[l], u_[l]);
      if (l + 1 < count) {  // the coarsest level gets no coarse-grid correction
        labelFreeComponents(levels_[l]);
        // Scaled corrections only happen inside the recursion (see applyCorrection).
        if (l > 0) allocateField(levels_[l], e_[l]);
      }
      if (l > 0) allocateField(levels_[l], f_[l]);  // the finest level has no right-hand side
    }
    if (count > 1) {  // sized for the finest level, used on every cycled level
      for (Field* field : {&previous_, &step_, &a_step_}) allocateField(levels_[0], *field);
    }
    for (size_t l = 0; l + 1 < levels_.size(); ++l) {
      Level& fine = levels_[l];
      const Level& coarse = levels_[l + 1];
      prolongationTable(fine.width, coarse.width, fine.coarse_x, fine.coarse_x_neighbour);
      prolongationTable(fine.height, coarse.height, fine.coarse_y, fine.coarse_y_neighbour);
      prolongationSources(fine, coarse);
    }
  }

  void solve(float* values, MultigridReport* report) {
    const int coarsest = static_cast<int>(levels_.size()) - 1;
    std::vector<double> residuals;
    int fine_cycles = 0;
    setDirichletValues(coarsest);
    smooth(coarsest, u_[coarsest].data(), nullptr, options_.coarsest_sweeps);
    for (int l = coarsest - 1; l >= 0; --l) {
      setDirichletValues(l);
      prolong<false>(l, u_[l + 1].data(), u_[l].data());
      const bool until_converged = l == 0 && options_.residual_tolerance > 0.0;
      const bool record = l == 0 && (options_.record_residuals || until_converged);
      const int cycles = until_converged ? options_.max_fine_cycles
                         : l == 0        ? options_.fine_cycles
                                         : options_.intermediate_cycles;
      if (record) residuals.push_back(residualNorm(0));
      for (int k = 0; k < cycles; ++k) {
        if (until_converged && residuals.back() <= options_.residual_tolerance) break;
        std::copy(u_[l].begin(), u_[l].end(), previous_.begin());
        cycled_ = l;
        vcycle(l, u_[l].data(), nullptr);
        accelerate(l, k == 0);
        if (l == 0) ++fine_cycles;
        if (record) residuals.push_back(residualNorm(0));
      }
    }
    if (coarsest == 0 && options_.record_residuals) residuals.push_back(residualNorm(0));
    if (report) {
      report->levels = static_cast<int>(levels_.size());
      report->fine_cycles = fine_cycles;
      report->converged = options_.residual_tolerance > 0.0 && coarsest > 0 &&
                          residuals.back() <= options_.residual_tolerance;
      report->residuals = residuals;
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

  void vcycle(int l, Px* u, const Px* f) {
    const int coarsest = static_cast<int>(levels_.size()) - 1;
    if (l == coarsest) {
      smooth(l, u, f, options_.coarsest_sweeps);
      return;
    }
    smooth(l, u, f, options_.pre_smoothing);
    restrictResidual(l, u, f, f_[l + 1].data());
    std::fill(u_[l + 1].begin(), u_[l + 1].end(), Px{});
    vcycle(l + 1, u_[l + 1].data(), f_[l + 1].data());
    applyCorrection(l, u, f);
    smooth(l, u, f, options_.post_smoothing);
  }

  // Replaces the update d = u - u_previous of the V-cycle just done on level l by the
  // combination a d + b s with the previous step s, per free component and channel (a
  // flexible-CG-like two-term recurrence). A region coupled to its Dirichlet pixels only
  // through gaps between barriers has a nearly singular Laplacian whose smooth error no
  // re-rasterised coarse grid represents well: the V-cycle alone removes only a few per cent
  // of it a cycle. (a, b) minimises the energy norm of the error; should that combination
  // leave a larger residual than the one before the cycle, the (a, b) that minimises the
  // residual is taken instead, so the residual never grows (a = b = 0 is a candidate).
  void accelerate(int l, bool first) {
    const Level& level = levels_[l];
    Px* __restrict u = u_[l].data();
    Px* __restrict d = previous_.data();  // holds u before the cycle; becomes the update
    Px* __restrict step = step_.data();
    Px* __restrict a_step = a_step_.data();
    // Over the whole layout: the buffers are sized for the finest level, and the ghost border
    // of this level must read 0.
    for (size_t p = 0; p < level.size; ++p) d[p] = level.component[p] >= 0 ? u[p] - d[p] : Px{};
    const size_t components = static_cast<size_t>(level.component_count);
    sums_.assign(components, {});
    for (int y = 0; y < level.height; ++y) {
      for (int x = 0; x < level.width; ++x) {
        const int p = level.index(x, y);
        const int k = level.component[p];
        if (k < 0) continue;
        const Px ad = -residualAt(level, d, nullptr, p);  // A d (d is 0 at Dirichlet pixels)
        const Px r = residualAt(level, u, nullptr, p);    // after the cycle: r0 - A d
        Sums& sum = sums_[k];
        accumulate(sum.d_ad, d[p] * ad);
        accumulate(sum.r_d, r * d[p]);
        accumulate(sum.ad_ad, ad * ad);
        accumulate(sum.r_ad, r * ad);
        accumulate(sum.r_r, r * r);
        if (first) continue;
        accumulate(sum.s_ad, step[p] * ad);
        accumulate(sum.s_as, step[p] * a_step[p]);
        accumulate(sum.r_s, r * step[p]);
        accumulate(sum.as_ad, a_step[p] * ad);
        accumulate(sum.as_as, a_step[p] * a_step[p]);
        accumulate(sum.r_as, r * a_step[p]);
      }
    }
    factors_.resize(components);
    step_factors_.resize(components);
    for (size_t k = 0; k < components; ++k) {
      const Sums& sum = sums_[k];
      for (int c = 0; c < C; ++c) {
        // With r0 = r + A d: energy minimum  [dAd sAd; sAd sAs] (a, b) = (r0.d, r0.s),
        // residual minimum [Ad.Ad Ad.As; Ad.As As.As] (a, b) = (r0.Ad, r0.As).
        const auto solve2 = [first](double m11, double m12, double m22, double v1, double v2) {
          const double det = m11 * m22 - m12 * m12;
          if (!first && m11 > 0.0 && det > 1e-12 * m11 * m22) {
            return std::pair{(v1 * m22 - v2 * m12) / det, (m11 * v2 - m12 * v1) / det};
          }
          return std::pair{m11 > 0.0 ? v1 / m11 : 0.0, 0.0};
        };
        const double ad_ad = sum.ad_ad[c], as_ad = sum.as_ad[c], as_as = sum.as_as[c];
        const double r0_ad = sum.r_ad[c] + ad_ad, r0_as = sum.r_as[c] + as_ad;
        const double r0_r0 = sum.r_r[c] + 2.0 * sum.r_ad[c] + ad_ad;
        auto [a, b] = solve2(sum.d_ad[c], sum.s_ad[c], sum.s_as[c], sum.r_d[c] + sum.d_ad[c],
                             sum.r_s[c] + sum.s_ad[c]);
        // |r0 - a Ad - b As|^2
        const double residual = r0_r0 - 2.0 * (a * r0_ad + b * r0_as) + a * a * ad_ad +
                                2.0 * a * b * as_ad + b * b * as_as;
        if (!(residual <= r0_r0)) std::tie(a, b) = solve2(ad_ad, as_ad, as_as, r0_ad, r0_as);
        setChannel(factors_[k], c, static_cast<float>(a));
        setChannel(step_factors_[k], c, static_cast<float>(b));
      }
    }
    for (int y = 0; y < level.height; ++y) {
      for (int x = 0; x < level.width; ++x) {
        const int p = level.index(x, y);
        const int k = level.component[p];
        if (k < 0) continue;
        const Px ad = -residualAt(level, d, nullptr, p);
        const Px a = factors_[k];
        Px x_new = a * d[p], ax_new = a * ad;
        if (!first) {
          x_new += step_factors_[k] * step[p];
          ax_new += step_factors_[k] * a_step[p];
        }
        u[p] += x_new - d[p];
        step[p] = x_new;
        a_step[p] = ax_new;
      }
    }
  }

  // Adds the interpolated coarse correction e to u. Below the level being cycled (inside the
  // recursion) it is scaled, per free component and channel, by the factor that minimises
  // the energy norm of that component's error: alpha = <r, e> / <e, A e>, r the residual
  // before the correction. The coarse problems are re-rasterised, not Galerkin products, so a
  // region coupled to its Dirichlet pixels only weakly (through gaps at barrier ends, say)
  // can be coupled much more weakly still on the coarse grid: its correction then overshoots
  // many times over and the plain V-cycle diverges. With the factor no correction increases
  // the energy of the error. On the cycled level itself accelerate() chooses the step.
  void applyCorrection(int l, Px* __restrict u, const Px* __restrict f) {
    if (l == cycled_) {
      prolong<true>(l, u_[l + 1].data(), u);
      return;
    }
    const Level& level = levels_[l];
    Px* __restrict e = e_[l].data();
    std::fill(e_[l].begin(), e_[l].end(), Px{});
    prolong<true>(l, u_[l + 1].data(), e);
    const size_t components = static_cast<size_t>(level.component_count);
    numerators_.assign(components, Sum{});
    denominators_.assign(components, Sum{});
    for (int y = 0; y < level.height; ++y) {
      for (int x = 0; x < level.width; ++x) {
        const int p = level.index(x, y);
        const int k = level.component[p];
        if (k < 0) continue;
        // -residualAt(e) is A e at a free pixel (e is 0 at Dirichlet pixels).
        accumulate(numerators_[k], residualAt(level, u, f, p) * e[p]);
        accumulate(denominators_[k], -residualAt(level, e, nullptr, p) * e[p]);
      }
    }
    factors_.resize(components);
    for (size_t k = 0; k < components; ++k) {
      for (int c = 0; c < C; ++c) {
        const double den = denominators_[k][c];
        setChannel(factors_[k], c, den > 0.0 ? static_cast<float>(numerators_[k][c] / den) : 0.0f);
      }
    }
    for (int y = 0; y < level.height; ++y) {
      for (int x = 0; x < level.width; ++x) {
        const int p = level.index(x, y);
        const int k = level.component[p];
        if (k >= 0) u[p] += factors_[k] * e[p];
      }
    }
  }

  // Red-black Gauss-Seidel on the free pixels: u_p = (f_p + sum w u_q) / sum w. The black
  // half-sweep trails the red one by a row, so one pass over memory does a full sweep.
  void smooth(int l, Px* u, const Px* f, int sweeps) const {
    const Level& level = levels_[l];
    for (int sweep = 0; sweep < sweeps; ++sweep) {
      for (int y = 0; y <= level.height; ++y) {
        if (f) {
          if (y < level.height) relaxRow<true>(level, u, f, y, y & 1);
          if (y > 0) relaxRow<true>(level, u, f, y - 1, y & 1);
        } else {
          if (y < level.height) relaxRow<false>(level, u, f, y, y & 1);
          if (y > 0) relaxRow<false>(level, u, f, y - 1, y & 1);
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
  static Px residualAt(const Level& level, const Px* __restrict u, const Px* __restrict f, int p) {
    const int s = level.stride;
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

  double residualNorm(int l) const {
    const Level& level = levels_[l];
    size_t free = 0;
    double squares = 0.0;
    for (int y = 0; y < level.height; ++y) {
      for (int x = 0; x < level.width; ++x) {
        const int p = level.index(x, y);
        free += !(level.mask[p] & kFixed);
        const Px r = residualAt(level, u_[l].data(), nullptr, p);
        for (int c = 0; c < C; ++c) {
          const double value = channel(r, c);
          squares += value * value;
        }
      }
    }
    return free ? std::sqrt(squares / (static_cast<double>(free) * C)) : 0.0;
  }

  // Computes the residual of level l and restricts it to level l + 1 in one pass. The
  // unscaled coarse Laplacian is 4x the fine one, so the coarse right-hand side is the sum
  // (not the mean) of the four children's residuals; a grid side of 1 pixel is not coarsened
  // and contributes no child, so its factor 2 is applied explicitly. Children beyond an odd
  // border fall into the ghost border, whose residual is 0. Residuals of free pixels in
  // Dirichlet coarse cells are redirected (see prolongationSources).
  void restrictResidual(int l, const Px* __restrict u, const Px* __restrict f,
                        Px* __restrict fc) const {
    const Level& fine = levels_[l];
    const Level& coarse = levels_[l + 1];
    const int s = fine.stride;
    const float scale = (fine.width == 1 ? 2.0f : 1.0f) * (fine.height == 1 ? 2.0f : 1.0f);
    for (int y = 0; y < coarse.height; ++y) {
      for (int x = 0; x < coarse.width; ++x) {
        const int p = fine.index(2 * x, 2 * y);
        fc[coarse.index(x, y)] =
            scale * (residualAt(fine, u, f, p) + residualAt(fine, u, f, p + 1) +
                     residualAt(fine, u, f, p + s) + residualAt(fine, u, f, p + s + 1));
      }
    }
    for (const Level::Redirect& redirect : fine.residual_redirects) {
      fc[redirect.coarse] += scale * redirect.weight * residualAt(fine, u, f, redirect.fine);
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
  std::vector<Field> u_, f_;
  std::vector<Field> e_;  // correction scratch per level
  // Dot products per free component, in double: a component can have 10^5 pixels.
  using Sum = std::array<double, C>;
  static void accumulate(Sum& sum, const Px& value) {
    for (int c = 0; c < C; ++c) sum[c] += channel(value, c);
  }
  int cycled_ = 0;
  std::vector<Sum> numerators_, denominators_;  // per free component (applyCorrection)
  std::vector<Px> factors_;
  struct Sums {  // accelerate's dot products (r is the residual after the cycle)
    Sum d_ad{}, r_d{}, ad_ad{}, r_ad{}, r_r{}, s_ad{}, s_as{}, r_s{}, as_ad{}, as_as{}, r_as{};
  };
  Field previous_, step_, a_step_;  // accelerate: finest cycled level's update, step, A step
  std::vector<Sums> sums_;
  std::vector<Px> step_factors_;
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
