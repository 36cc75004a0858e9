#include "vicc_glyphs/render/multigrid.hpp"

#if defined(__SSE__)
#include <xmmintrin.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include <opencv2/imgproc.hpp>

#include "multigrid_deflation.hpp"
#include "multigrid_levels.hpp"
#include "multigrid_local_relaxation.hpp"
#include "vicc_glyphs/numerics/banded_cholesky.hpp"
#include "vicc_glyphs/render/constant_regions.hpp"
#include "vicc_glyphs/render/pixel_buffer.hpp"

namespace vicc_glyphs {
namespace multigrid_detail {
namespace {

// A pixel's values. Colour is stored as four floats in a GCC/Clang vector type, so that every
// per-pixel operation is one 4-wide SIMD instruction (the fourth is no channel: not always
// written, never read into a result or a decision); a single channel (the blur field) is a
// plain float.
typedef float Float4 __attribute__((vector_size(16)));

template <int C>
using PixelValue = std::conditional_t<C == 3, Float4, float>;

// What the conjugate-gradient loop of the finest level recorded (see MultigridReport).
struct FineProgress {
  int iterations = 0;
  bool converged = false;
  bool at_float_resolution = false;
  std::vector<double> residuals, error_estimates, updates;
};

template <int C>
class Multigrid {
  using Px = PixelValue<C>;
  using Field = render_detail::PixelVector<Px>;
  // Dot products per channel, in double: a level can have 10^7 pixels.
  using Sum = std::array<double, C>;
  // Called with a row index of the finest level (see vcycle).
  using RowHook = std::function<void(int)>;

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
    for (size_t l = 1; l < count; ++l) {
      CoarseLevel& coarse = coarse_[l - 1];
      resizeCoarseLevel(sizes[l].first, sizes[l].second, coarse);
      if (l == 1) {
        coarsen(fine_, transfers_[0], coarse, flags_);
      } else {
        coarsen(coarse_[l - 2], transfers_[l - 1], coarse, flags_);
      }
      allocateField(coarse.size, coarse.stride, coarse.height, u_[l]);
      allocateField(coarse.size, coarse.stride, coarse.height, f_[l]);
    }
    allocateField(fine_.size, fine_.stride, fine_.height, u_[0]);
    for (Field* field : {&r_, &p_, &ap_}) {
      allocateField(fine_.size, fine_.stride, fine_.height, *field);
    }
    // The V-cycles write z only at free pixels (starting from zero without reading it there):
    // its Dirichlet pixels must read 0.
    z_.resize(fine_.size);
    std::fill(z_.begin(), z_.end(), Px{});
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
        const Px* f = f_[l].data();
        restrictFrom(
            coarse_[l - 1], l, [f](size_t p) { return f[p]; }, f_[l + 1].data());
      }
      solveCoarsest(u_[coarsest].data(), f_[coarsest].data());
      next_to_finest_cycles_ = 0;
      for (int l = coarsest - 1; l >= 1; --l) {
        prolong<false>(l, u_[l + 1].data(), u_[l].data());
        if (l == 1) {
          cycleNextToFinest();
        } else {
          for (int k = 0; k < options_.intermediate_cycles; ++k) {
            vcycle(l, u_[l].data(), f_[l].data(), false);
          }
        }
      }
      prolong<true>(0, u_[1].data(), u_[0].data());
    }
    FineProgress progress;
    conjugateGradients(progress);
    if (report) {
      report->levels = levelCount();
      report->fine_cycles = progress.iterations;
      report->next_to_finest_cycles = coarsest > 1 ? next_to_finest_cycles_ : 0;
      report->converged = progress.converged;
      report->stopped_at_float_resolution = progress.at_float_resolution;
      report->residuals = std::move(progress.residuals);
      report->error_estimates = std::move(progress.error_estimates);
      report->updates = std::move(progress.updates);
    }
    finestValues(values);
  }

 private:
  int levelCount() const { return static_cast<int>(coarse_.size()) + 1; }

  // FMG's V-cycles on level 1, and one more when the last one still moved the solution by more
  // than `extra_next_to_finest_cycle_above` tolerances: the finest level's start is only as
  // good as this solve (with a fixed iteration count, no tolerance, never).
  void cycleNextToFinest() {
    const int cycles = options_.next_to_finest_cycles;
    const double above = options_.tolerance * options_.extra_next_to_finest_cycle_above;
    Field& u = u_[1];
    for (int k = 0; k < cycles; ++k) {
      if (above > 0.0 && k + 1 == cycles) before_last_cycle_ = u;
      vcycle(1, u.data(), f_[1].data(), false);
    }
    next_to_finest_cycles_ = cycles;
    if (above > 0.0 && cycles > 0 && largestChange(u, before_last_cycle_) > above) {
      vcycle(1, u.data(), f_[1].data(), false);
      ++next_to_finest_cycles_;
    }
  }

  // The largest magnitude of after - before over the points and channels.
  static double largestChange(const Field& after, const Field& before) {
    Px most{};
    for (size_t i = 0; i < after.size(); ++i) most = largerMagnitude(most, after[i] - before[i]);
    return largestChannel(most);
  }

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

  // max(largest, |value|) per channel (largest is not negative).
  static Px largerMagnitude(const Px& largest, const Px& value) {
    if constexpr (C == 3) {
#if defined(__SSE__)
      return _mm_max_ps(largest, _mm_andnot_ps(_mm_set1_ps(-0.0f), value));  // sign cleared
#else
      const Px magnitude = value < 0 ? -value : value;
      return magnitude > largest ? magnitude : largest;
#endif
    } else {
      return std::max(largest, std::abs(value));
    }
  }

  static void accumulate(Sum& sum, const Px& value) {
    for (int c = 0; c < C; ++c) sum[c] += channel(value, c);
  }

  static Sum toSum(const Px& value) {
    Sum sum{};
    accumulate(sum, value);
    return sum;
  }

  // num / den per channel; 0 where den is not positive (a channel already solved exactly).
  static double largestChannel(const Px& value) {
    double most = 0.0;
    for (int c = 0; c < C; ++c) most = std::max(most, static_cast<double>(channel(value, c)));
    return most;
  }

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
    // Only the cells worked out point by point can have other weights (the rest are bilinear).
    for (int pass = 0; pass < 2; ++pass) {
      for (const int c : coarse.worked_out_cells) {
        if (isBilinear(transfer[c])) continue;
        const int i = c % coarse.stride - 1, j = c / coarse.stride - 1;
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

  // Preconditioned conjugate gradients on the finest level from u_[0]; the preconditioner is
  // one V-cycle from zero on the residual. r, z, p and A p are 0 at Dirichlet pixels and in the
  // ghost border, so the passes need no mask. From the second iteration on, when the first
  // shows slow convergence, the directions are deflated (see DeflationSpace); CG restarts there.
  void conjugateGradients(FineProgress& progress) {
    const bool until_converged = options_.tolerance > 0.0;
    const bool record = options_.record_residuals;  // rms statistics only when asked for
    const int iterations = until_converged ? options_.max_fine_cycles : options_.fine_cycles;
    const Px* __restrict u = u_[0].data();
    Px* __restrict r = r_.data();
    Px squares{};  // in float: only the deflation's decision reads it unless recording
    seeds_.clear();
    for (int y = 0; y < fine_.height; ++y) {  // the ghost border's residual is 0
      const int begin = fine_.index(0, y), end = fine_.index(fine_.width, y);
      Px row_largest{};
      for (int i = begin; i < end; ++i) {
        r[i] = residualAt(fine_, u, nullptr, static_cast<size_t>(i));
        squares += r[i] * r[i];
        row_largest = largerMagnitude(row_largest, r[i]);
      }
      if (options_.local_relaxation > 0 && exceeds(row_largest, kLocalRelaxationResidual)) {
        for (int i = begin; i < end; ++i) {
          if (exceeds(r[i], kLocalRelaxationResidual)) seeds_.push_back(i);
        }
      }
    }
    squares = relaxStartLocally(squares);
    const double start_residual =
        record ? rms(sumRows([&](size_t i) { return r[i] * r[i]; })) : rms(toSum(squares));
    if (record) progress.residuals.push_back(start_residual);
    double first_residual = 0.0;  // after the first iteration
    Sum rz_previous{};
    alphas_.clear();
    betas_.clear();
    ritz_floor_.fill(1.0);
    deflating_ = false;
    bool restart = true;
    for (int k = 0; k <= iterations; ++k) {
      const bool last = k == iterations;
      if (last && !until_converged) break;  // a fixed count needs no estimate of the result
      // Deflate when the first iteration shows that two more at its rate would not do (most
      // icons converge in 0-2 iterations and never pay for it): the first estimate shrunk
      // twice by the first iteration's residual reduction. Only a matter of cost.
      if (k == 1 && !last && options_.deflation &&
          first_estimate_ * std::pow(first_residual / start_residual, 2) > options_.tolerance &&
          startDeflation()) {
        restart = true;
      }
      Px largest{};
      Sum rz = precondition(largest);
      bool projected = false;  // the deflation's start moved this iterate: same estimate entry
      if (!deflating_) {
        const double estimate = errorEstimate(largest);
        if (stops(estimate, last, false, progress)) break;
        if (k == 0) first_estimate_ = estimate;
        // A slow mode with a small residual (a long channel behind a gap) shows only in the
        // estimate: deflate if one more iteration at the first one's rate would not do, at the
        // price of the V-cycle redone for the projected residual.
        if (k == 1 && options_.deflation &&
            estimate * (estimate / first_estimate_) > options_.tolerance && startDeflation()) {
          restart = projected = true;
          largest = Px{};
          rz = precondition(largest);
        }
      }
      const Px beta = restart ? Px{} : ratio(rz, rz_previous);
      rz_previous = rz;
      const Px alpha = ratio(rz, updateDirection(beta, restart, largest));
      // A fixed count: once the V-cycle's correction is below float resolution, further steps
      // change no pixel but lose CG's orthogonality in float arithmetic, and the iterate then
      // drifts away again (virus, 100 cycles: residual 2e-13 after 9, grey blocks after 100).
      if (!until_converged && largestChannel(largest) < kFloatResolution) {
        progress.at_float_resolution = true;
        break;
      }
      // Deflated, the correction's largest magnitude is known only now (the last direction is
      // then computed in vain).
      if (deflating_ && stops(errorEstimate(largest), last, projected, progress)) break;
      restart = false;
      alphas_.push_back(alpha);
      betas_.push_back(beta);
      const double residual = step(alpha, record ? &progress : nullptr, k == 0);
      if (k == 0) first_residual = residual;
      ++progress.iterations;
    }
  }

  // Gauss-Seidel sweeps (forwards, then backwards) on the free pixels around the seeds, the
  // pixels whose start residual is large (see LocalRelaxationSet), and their residuals updated;
  // returns `squares` (the residuals' sum of squares) updated. Not when the seeds are a large
  // share of the image: the start is then poor everywhere, a matter for the V-cycles. Isolated
  // spots (few seeds: a waved contour's tips and slits) get a wider square and more sweeps.
  Px relaxStartLocally(Px squares) {
    if (seeds_.empty() || seeds_.size() > free_count_ / kMaxSeedShare) return squares;
    const bool isolated = seeds_.size() <= free_count_ / kIsolatedSeedShare;
    local_.build(fine_, seeds_, isolated ? kIsolatedSpotRadius : kLocalRelaxationRadius);
    const int sweeps = isolated ? std::max(options_.local_relaxation, options_.isolated_spot_sweeps)
                                : options_.local_relaxation;
    Px* __restrict u = u_[0].data();
    Px* __restrict r = r_.data();
    const std::vector<int>& pixels = local_.pixels();
    for (int sweep = 0; sweep < sweeps; ++sweep) {
      for (const int p : pixels) relaxAt<false>(u, nullptr, p);
      for (auto it = pixels.rbegin(); it != pixels.rend(); ++it) relaxAt<false>(u, nullptr, *it);
    }
    for (const int p : local_.affected()) {
      squares -= r[p] * r[p];
      r[p] = residualAt(fine_, u, nullptr, static_cast<size_t>(p));
      squares += r[p] * r[p];
    }
    return squares;
  }

  // Whether a channel of `value` exceeds `threshold` in magnitude.
  static bool exceeds(const Px& value, float threshold) {
    if constexpr (C == 3) {
#if defined(__SSE__)
      // Lanes 0-2 only: the fourth is padding (kept 0, see solveCoarsest), not a channel.
      const __m128 above = _mm_cmpgt_ps(largerMagnitude(Px{}, value), _mm_set1_ps(threshold));
      return (_mm_movemask_ps(above) & 7) != 0;
#else
      const auto above = largerMagnitude(Px{}, value) > threshold;  // lanes 0 or -1
      return (above[0] | above[1] | above[2]) != 0;
#endif
    } else {
      return std::abs(value) > threshold;
    }
  }

  // Records the estimate of the current iterate (`replace`: instead of the last one); at the
  // tolerance or the last iteration adds the estimate's correction (for free) and returns true.
  bool stops(double estimate, bool last, bool replace, FineProgress& progress) {
    if (options_.tolerance > 0.0 || options_.record_residuals) {
      if (replace) progress.error_estimates.pop_back();
      progress.error_estimates.push_back(estimate);
    }
    progress.converged = options_.tolerance > 0.0 && estimate <= options_.tolerance;
    if (!progress.converged && !last) return false;
    Px* __restrict u = u_[0].data();
    const Px* __restrict z = z_.data();
    if (deflating_) {
      const std::uint32_t* labels = deflation_.labels();
      for (size_t i = 0; i < fine_.size; ++i) u[i] += z[i] - coefficients_[labels[i]];
    } else {
      for (size_t i = 0; i < fine_.size; ++i) u[i] += z[i];
    }
    return true;
  }

  // z = B r, the V-cycle's correction; returns r . z per channel (r . (z - Z c) when deflating:
  // the same, as r is orthogonal to Z's columns) and, not deflating, sets `largest` to max |z|
  // per channel, both summed as the post-smoothing finishes each row. Deflating, the
  // coefficients c of E c = Z^T A z (A-DEF2: z - Z c is A-orthogonal to the pieces' constants;
  // no Q r term, r stays orthogonal to them), which updateDirection subtracts.
  Sum precondition(Px& largest) {
    const Px* __restrict r = r_.data();
    Px* __restrict z = z_.data();
    Sum rz{};
    const bool deflating = deflating_;
    const RowHook row_statistics = [&, r, z](int y) {
      Px row{};
      for (int i = fine_.index(0, y), end = fine_.index(fine_.width, y); i < end; ++i) {
        if (!deflating) largest = largerMagnitude(largest, z[i]);
        row += r[i] * z[i];
      }
      accumulate(rz, row);
    };
    vcycle(0, z, r, true, &row_statistics);
    if (deflating) solveDeflated(boundaryProduct(z));
    return rz;
  }

  // z = (B A) e: the error e itself where B inverts A well, a fraction of it (an eigenvalue
  // of B A) where not, e.g. for a region that reaches its Dirichlet pixels through a gap. So
  // the estimate divides by the smallest eigenvalue CG has met (before a restart: the one met
  // before it, until the restarted CG has met one itself).
  double errorEstimate(const Px& largest) const {
    double estimate = 0.0;
    for (int c = 0; c < C; ++c) {
      const double smallest =
          alphas_.empty() ? ritz_floor_[c] : std::min(1.0, smallestRitzValue(alphas_, betas_, c));
      estimate = std::max(estimate, channel(largest, c) / std::max(smallest, kSmallestRitz));
    }
    return estimate;
  }

  // u += alpha p, r -= alpha A p; with `progress` also records the rms update and residual.
  // Returns the rms residual with `progress` or `measure` (else 0).
  double step(const Px& alpha, FineProgress* progress, bool measure) {
    Px* __restrict u = u_[0].data();
    Px* __restrict r = r_.data();
    const Px* __restrict p = p_.data();
    const Px* __restrict ap = ap_.data();
    if (!progress && !measure) {
      for (size_t i = 0; i < fine_.size; ++i) {
        u[i] += alpha * p[i];
        r[i] -= alpha * ap[i];
      }
      return 0.0;
    }
    Sum update_squares{}, rr{};
    for (int y = 0; y < fine_.height; ++y) {
      Px row_updates{}, row_residuals{};
      for (int i = fine_.index(0, y), end = fine_.index(fine_.width, y); i < end; ++i) {
        const Px update = alpha * p[i];
        u[i] += update;
        r[i] -= alpha * ap[i];
        row_updates += update * update;
        row_residuals += r[i] * r[i];
      }
      accumulate(update_squares, row_updates);
      accumulate(rr, row_residuals);
    }
    if (progress) {
      progress->residuals.push_back(rms(rr));
      progress->updates.push_back(rms(update_squares));
    }
    return rms(rr);
  }

  // Builds the deflation space and projects the iterate onto it; returns whether CG restarts
  // (false when there is nothing to deflate). The Ritz values met so far stay the estimate's
  // floor until the restarted CG has its own.
  bool startDeflation() {
    deflation_.build(fine_, singletonPixels());
    if (deflation_.count() == 0) return false;
    for (int c = 0; c < C; ++c) {
      ritz_floor_[c] = std::min(1.0, smallestRitzValue(alphas_, betas_, c));
    }
    alphas_.clear();
    betas_.clear();
    deflateStart();
    deflating_ = true;
    return true;
  }

  // The deflation's singleton pieces: the free pixels within kSingletonRadius of those where
  // the last V-cycle's correction z (B r) is at least a share of its largest magnitude over
  // all channels, the first of kSingletonShares that gives at most one per kMaxSingletonShare
  // free pixels and at most kMaxSingletons (else none: the factorisation of E would cost more
  // than the iterations it saves).
  const std::vector<int>& singletonPixels() {
    static const std::vector<int> kNone;
    if (!options_.singleton_pieces) return kNone;
    const Px* z = z_.data();
    Px magnitudes{};
    for (size_t i = 0; i < fine_.size; ++i) magnitudes = largerMagnitude(magnitudes, z[i]);
    float largest = 0.0f;
    for (int c = 0; c < C; ++c) largest = std::max(largest, channel(magnitudes, c));
    if (!(largest > 0.0f)) return kNone;
    const size_t limit = std::min(free_count_ / kMaxSingletonShare, kMaxSingletons);
    const int side = 2 * kSingletonRadius + 1;
    const cv::Mat square = cv::getStructuringElement(cv::MORPH_RECT, cv::Size(side, side));
    // The fine level's layout, ghost border included (its marks stay 0, the dilation's are
    // not read).
    seed_marks_.create(fine_.height + 2, fine_.stride, CV_8U);
    for (const float share : kSingletonShares) {
      const float threshold = share * largest;
      std::uint8_t* marks = seed_marks_.ptr<std::uint8_t>();
      size_t seeds = 0;
      for (int i = 0; i < static_cast<int>(fine_.size); ++i) {
        marks[i] = fine_.isFree(i) && exceeds(z[i], threshold);
        seeds += marks[i];
      }
      if (seeds > limit) continue;
      cv::dilate(seed_marks_, square_marks_, square);
      const std::uint8_t* inside = square_marks_.ptr<std::uint8_t>();
      singletons_.clear();
      for (int i = 0; i < static_cast<int>(fine_.size) && singletons_.size() <= limit; ++i) {
        if (inside[i] && fine_.isFree(i)) singletons_.push_back(i);
      }
      if (singletons_.size() <= limit) return singletons_;
    }
    return kNone;
  }

  // A-DEF2's start: u + Z E^-1 Z^T r, whose residual is orthogonal to the regions' constants
  // (then every later one is: the directions are A-orthogonal to them).
  void deflateStart() {
    const int count = deflation_.count();
    std::vector<Sum> sums(static_cast<size_t>(count) + 1, Sum{});
    const std::uint32_t* labels = deflation_.labels();
    const Px* __restrict r = r_.data();
    for (size_t i = 0; i < fine_.size; ++i) accumulate(sums[labels[i]], r[i]);
    regions_.resize(count, C);
    for (int k = 0; k < count; ++k) {
      for (int c = 0; c < C; ++c) regions_(k, c) = sums[k][c];
    }
    solveDeflated(regions_);
    Px* __restrict u = u_[0].data();
    for (size_t i = 0; i < fine_.size; ++i) u[i] += coefficients_[labels[i]];
    for (const int p : deflation_.boundary()) r_[p] -= operatorOfCoefficients(p);
  }

  // Z^T A v, which only the boundary pixels' values enter (A Z is 0 elsewhere).
  Eigen::MatrixXd& boundaryProduct(const Px* v) {
    regions_.setZero(deflation_.count(), C);
    const std::uint32_t* labels = deflation_.labels();
    const std::uint32_t none = static_cast<std::uint32_t>(deflation_.count());
    const int s = fine_.stride;
    for (const int p : deflation_.boundary()) {
      const std::uint8_t m = fine_.mask[p];
      const std::uint32_t k = labels[p];
      for (const auto& [link, q] :
           {std::pair{kLeft, p - 1}, {kRight, p + 1}, {kUp, p - s}, {kDown, p + s}}) {
        if (!(m & link) || labels[q] == k) continue;
        for (int c = 0; c < C; ++c) {
          regions_(k, c) += channel(v[p], c);
          if (labels[q] != none) regions_(labels[q], c) -= channel(v[p], c);
        }
      }
    }
    return regions_;
  }

  // coefficients_ = E^-1 g per channel, and 0 for the pixels outside every region.
  void solveDeflated(Eigen::MatrixXd& g) {
    deflation_.solve(g);
    const int count = deflation_.count();
    coefficients_.assign(static_cast<size_t>(count) + 1, Px{});
    for (int k = 0; k < count; ++k) {
      for (int c = 0; c < C; ++c) setChannel(coefficients_[k], c, static_cast<float>(g(k, c)));
    }
  }

  // (A Z c)(p) for the coefficients c: the differences across the links that leave p's region.
  Px operatorOfCoefficients(int p) const {
    const std::uint32_t* labels = deflation_.labels();
    const std::uint8_t m = fine_.mask[p];
    const int s = fine_.stride;
    Px sum{};
    for (const auto& [link, q] :
         {std::pair{kLeft, p - 1}, {kRight, p + 1}, {kUp, p - s}, {kDown, p + s}}) {
      if (m & link) sum += coefficients_[labels[p]] - coefficients_[labels[q]];
    }
    return sum;
  }

  // The smallest eigenvalue of the preconditioned operator B A that CG has met in channel c:
  // the smallest Ritz value of the Lanczos tridiagonal matrix of its steps (diagonal
  // 1/alpha_j + beta_j/alpha_j-1, off-diagonal sqrt(beta_j)/alpha_j-1), by bisection on Sturm
  // sequence counts. 1 before the first step (B A's eigenvalues lie in (0, 1]: a symmetric
  // V-cycle with Galerkin coarse operators is a convergent iteration).
  static double smallestRitzValue(const std::vector<Px>& alphas, const std::vector<Px>& betas,
                                  int c) {
    std::vector<double> diagonal, off_diagonal;  // off_diagonal[j]: between j and j + 1
    for (size_t j = 0; j < alphas.size(); ++j) {
      const double alpha = channel(alphas[j], c);
      if (!(alpha > 0.0)) break;  // the channel was solved exactly
      double d = 1.0 / alpha;
      if (j > 0) {
        const double beta = std::max(0.0, static_cast<double>(channel(betas[j], c)));
        const double previous = channel(alphas[j - 1], c);
        d += beta / previous;
        off_diagonal.push_back(std::sqrt(beta) / previous);
      }
      diagonal.push_back(d);
    }
    if (diagonal.empty()) return 1.0;
    const size_t m = diagonal.size();
    double upper = 0.0;  // Gershgorin
    for (size_t j = 0; j < m; ++j) {
      const double left = j > 0 ? off_diagonal[j - 1] : 0.0;
      const double right = j + 1 < m ? off_diagonal[j] : 0.0;
      upper = std::max(upper, diagonal[j] + left + right);
    }
    double lower = 0.0;
    for (int step = 0; step < 50; ++step) {
      const double middle = 0.5 * (lower + upper);
      int below = 0;  // eigenvalues below `middle`: negative pivots of T - middle I
      double pivot = 1.0;
      for (size_t j = 0; j < m; ++j) {
        const double coupling = j > 0 ? off_diagonal[j - 1] : 0.0;
        pivot = diagonal[j] - middle - (j > 0 ? coupling * coupling / pivot : 0.0);
        if (pivot == 0.0) pivot = -1e-300;
        if (pivot < 0.0) ++below;
      }
      (below > 0 ? upper : lower) = middle;
    }
    return upper;
  }

  // p = y + beta p (the first time p = y: p holds garbage) and A p, row by row (A p of a row
  // needs p of the rows around it, so it trails by one); returns p . A p. y is z, or deflating
  // z - Z c, whose largest magnitude per channel then goes to `largest`.
  Sum updateDirection(const Px& beta, bool first, Px& largest) {
    const Px* __restrict z = z_.data();
    Px* __restrict p = p_.data();
    Px* __restrict ap = ap_.data();
    Sum total{};
    const auto product_row = [&](int y) {
      Px row{};
      for (int i = fine_.index(0, y), end = fine_.index(fine_.width, y); i < end; ++i) {
        ap[i] = operatorAt(fine_, p, static_cast<size_t>(i));
        row += p[i] * ap[i];
      }
      accumulate(total, row);
    };
    const std::uint32_t* labels = deflating_ ? deflation_.labels() : nullptr;
    const Px* coefficients = coefficients_.data();
    const Px scale = first ? Px{} : beta;  // p holds garbage the first time: not read then
    for (int y = 0; y < fine_.height; ++y) {
      const int begin = fine_.index(0, y), end = fine_.index(fine_.width, y);
      if (labels) {
        for (int i = begin; i < end; ++i) {
          const Px deflated = z[i] - coefficients[labels[i]];
          largest = largerMagnitude(largest, deflated);
          p[i] = first ? deflated : deflated + scale * p[i];
        }
      } else if (first) {
        std::copy(z + begin, z + end, p + begin);
      } else {
        for (int i = begin; i < end; ++i) p[i] = z[i] + beta * p[i];
      }
      if (y > 0) product_row(y - 1);
    }
    product_row(fine_.height - 1);
    return total;
  }

  // Sums term(i) over the interior of the finest level (per row in float, then in double).
  template <class Term>
  Sum sumRows(Term&& term) const {
    Sum total{};
    for (int y = 0; y < fine_.height; ++y) {
      Px row{};
      for (int i = fine_.index(0, y), end = fine_.index(fine_.width, y); i < end; ++i) {
        row += term(static_cast<size_t>(i));
      }
      accumulate(total, row);
    }
    return total;
  }

  // One V-cycle on level l for A u = f, from u or, with `from_zero`, from 0 (u is then not read
  // at the free points; its other points must be 0). On level 0 `final_row` (if any) is called
  // with each row of u as soon as the post-smoothing has finished it.
  void vcycle(int l, Px* u, const Px* f, bool from_zero, const RowHook* final_row = nullptr) {
    const int coarsest = levelCount() - 1;
    if (l == coarsest) {
      solveCoarsest(u, f);
      return;
    }
    const int pre = options_.pre_smoothing, post = options_.post_smoothing;
    if (from_zero && pre == 0) zeroFree(l, u);
    if (l == 0) {
      smoothFine(u, f, pre, false, from_zero);
    } else {
      smoothCoarse(coarse_[l - 1], u, f, pre, false, from_zero);
    }
    if (l == 0 && pre > 0) {
      // The pre-smoothing ended with the black half-sweep: the black pixels' residual is 0.
      const FineLevel& fine = fine_;
      restrictFrom<true>(
          fine, l, [&](size_t p) { return residualAt(fine, u, f, p); }, f_[1].data());
    } else {
      restrictResidual(l, u, f, f_[l + 1].data());
    }
    vcycle(l + 1, u_[l + 1].data(), f_[l + 1].data(), true);
    prolong<true>(l, u_[l + 1].data(), u);
    // The adjoint of the pre-smoothing.
    if (l == 0) {
      smoothFine(u, f, post, true, false, final_row);
    } else {
      smoothCoarse(coarse_[l - 1], u, f, post, true, false);
    }
  }

  void zeroFree(int l, Px* u) const {
    const size_t size = l == 0 ? fine_.size : coarse_[l - 1].size;
    for (size_t p = 0; p < size; ++p) {
      if (l > 0 || fine_.isFree(static_cast<int>(p))) u[p] = Px{};
    }
  }

  // Red-black Gauss-Seidel on the free pixels of the finest level: u_p = (f_p + sum w u_q) /
  // sum w, red pixels (x + y even) first, or black first if `black_first`. The second
  // half-sweep trails the first by a row, so one pass over memory does a full sweep. From
  // zero, the first half-sweep reads no neighbours.
  void smoothFine(Px* u, const Px* f, int sweeps, bool black_first, bool from_zero,
                  const RowHook* final_row = nullptr) const {
    const int order = black_first ? 1 : 0;
    for (int sweep = 0; sweep < sweeps; ++sweep) {
      const bool leading_from_zero = from_zero && sweep == 0;
      for (int y = 0; y <= fine_.height; ++y) {
        const int first_x = (y + order) & 1;  // leading row y, trailing row y - 1: other colour
        if (y < fine_.height) {
          if (leading_from_zero) {
            relaxRowFromZero(u, f, y, first_x);
          } else if (f) {
            relaxRow<true>(u, f, y, first_x);
          } else {
            relaxRow<false>(u, f, y, first_x);
          }
        }
        if (y > 0) {
          if (f) {
            relaxRow<true>(u, f, y - 1, first_x);
          } else {
            relaxRow<false>(u, f, y - 1, first_x);
          }
          if (final_row && sweep + 1 == sweeps) (*final_row)(y - 1);
        }
      }
    }
    if (final_row && sweeps == 0) {
      for (int y = 0; y < fine_.height; ++y) (*final_row)(y);
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
        relaxAt<kHasRhs>(u, f, p);
      }
    }
  }

  // Gauss-Seidel at free pixel p of the finest level, any links.
  template <bool kHasRhs>
  __attribute__((always_inline)) void relaxAt(Px* __restrict u, const Px* __restrict f,
                                              int p) const {
    const int s = fine_.stride;
    const LinkWeights& w = kWeights[fine_.mask[p] & kAllLinks];
    Px sum = w.left * u[p - 1] + w.right * u[p + 1] + w.up * u[p - s] + w.down * u[p + s];
    if constexpr (kHasRhs) sum += f[p];
    u[p] = sum * w.inv_degree;
  }

  // The first half-sweep from u = 0: u_p = f_p / sum w.
  void relaxRowFromZero(Px* __restrict u, const Px* __restrict f, int y, int first_x) const {
    const std::uint8_t* __restrict mask = fine_.mask.data();
    for (int p = fine_.index(first_x, y), end = fine_.index(fine_.width, y); p < end; p += 2) {
      const std::uint8_t m = mask[p];
      if (!(m & kFixed)) u[p] = f[p] * kWeights[m].inv_degree;
    }
  }

  // Lexicographic Gauss-Seidel on a coarse level, forwards or (the adjoint) backwards. Points
  // that are not unknowns have zero rows and stay 0. From zero, the first (forward) sweep
  // reads only the neighbours it has already relaxed. Each update is written as the part from
  // every neighbour but the one relaxed just before, less that one's coupling over the centre
  // times its new value (carried in a register): the chain from point to point is then one
  // multiply and one subtract, and the rest of a point's work overlaps the previous point's
  // (summed in the stencil's order, the chain was six operations long and bound the sweep).
  static void smoothCoarse(const CoarseLevel& level, Px* __restrict u, const Px* __restrict f,
                           int sweeps, bool backwards, bool from_zero) {
    for (int sweep = 0; sweep < sweeps; ++sweep) {
      const bool first_from_zero = from_zero && sweep == 0;  // always forwards
      for (int row = 0; row < level.height; ++row) {
        const int y = backwards && !first_from_zero ? level.height - 1 - row : row;
        if (first_from_zero) {
          relaxRowFromZero(level, u, f, y);
        } else if (backwards) {
          relaxRowBackwards(level, u, f, y);
        } else {
          relaxRowForwards(level, u, f, y);
        }
      }
    }
  }

  static void relaxRowForwards(const CoarseLevel& level, Px* __restrict u, const Px* __restrict f,
                               int y) {
    const std::uint8_t* __restrict regular = level.regular.data();
    const float* __restrict inverse = level.inverse_centre.data();
    const float* __restrict east = level.east.data();
    const RegularRow stencil(level.regular_stencil);
    const int s = level.stride;
    Px west = u[level.index(-1, y)];  // the ghost border: 0
    for (int p = level.index(0, y), end = level.index(level.width, y); p < end; ++p) {
      if (regular[p]) {
        const Px others = stencil.edge * ((u[p - s] + u[p + s]) + u[p + 1]) +
                          stencil.corner * regularCorners(u, p, s);
        west = (f[p] - others) * stencil.inverse_centre - stencil.edge_over_centre * west;
      } else {
        const Px others = backwardOffDiagonalButWest(level, u, p) + forwardOffDiagonal(level, u, p);
        west = (f[p] - others) * inverse[p] - (east[p - 1] * inverse[p]) * west;
      }
      u[p] = west;
    }
  }

  // The mirror image of relaxRowForwards (east for west). Kept apart: one template for both
  // directions rendered the ladybug 2-4 % slower (session 36, alternated three times).
  static void relaxRowBackwards(const CoarseLevel& level, Px* __restrict u, const Px* __restrict f,
                                int y) {
    const std::uint8_t* __restrict regular = level.regular.data();
    const float* __restrict inverse = level.inverse_centre.data();
    const float* __restrict east = level.east.data();
    const RegularRow stencil(level.regular_stencil);
    const int s = level.stride;
    Px east_value = u[level.index(level.width, y)];  // the ghost border: 0
    for (int p = level.index(level.width - 1, y), end = level.index(0, y); p >= end; --p) {
      if (regular[p]) {
        const Px others = stencil.edge * ((u[p - s] + u[p + s]) + u[p - 1]) +
                          stencil.corner * regularCorners(u, p, s);
        east_value =
            (f[p] - others) * stencil.inverse_centre - stencil.edge_over_centre * east_value;
      } else {
        const Px others = backwardOffDiagonal(level, u, p) + forwardOffDiagonalButEast(level, u, p);
        east_value = (f[p] - others) * inverse[p] - (east[p] * inverse[p]) * east_value;
      }
      u[p] = east_value;
    }
  }

  // The first forward sweep from zero: only the neighbours before p have values.
  static void relaxRowFromZero(const CoarseLevel& level, Px* __restrict u, const Px* __restrict f,
                               int y) {
    const float* __restrict inverse = level.inverse_centre.data();
    const float* __restrict east = level.east.data();
    Px west{};
    for (int p = level.index(0, y), end = level.index(level.width, y); p < end; ++p) {
      const Px others = backwardOffDiagonalButWest(level, u, p);
      west = (f[p] - others) * inverse[p] - (east[p - 1] * inverse[p]) * west;
      u[p] = west;
    }
  }

  // The regular stencil's couplings as the smoother uses them.
  struct RegularRow {
    explicit RegularRow(const Stencil& stencil)
        : edge(stencil[kE]),
          corner(stencil[kSE]),
          inverse_centre(1.0f / stencil[kC]),
          edge_over_centre(stencil[kE] / stencil[kC]) {}
    float edge, corner, inverse_centre, edge_over_centre;
  };

  __attribute__((always_inline)) static Px regularCorners(const Px* __restrict u, int p, int s) {
    return (u[p - s - 1] + u[p - s + 1]) + (u[p + s - 1] + u[p + s + 1]);
  }

  // The off-diagonal part of a regular coarse row times u (the couplings as arguments, so that
  // a loop can keep them in registers). The regular stencil is symmetric: one coupling for the
  // four edge neighbours, one for the four corners.
  __attribute__((always_inline)) static Px regularOffDiagonal(const Px* __restrict u, int p, int s,
                                                              float edge, float corner) {
    const Px edges = (u[p - 1] + u[p + 1]) + (u[p - s] + u[p + s]);
    const Px corners = (u[p - s - 1] + u[p - s + 1]) + (u[p + s - 1] + u[p + s + 1]);
    return edge * edges + corner * corners;
  }

  // The off-diagonal part of a coarse row times u.
  __attribute__((always_inline)) static Px offDiagonal(const CoarseLevel& level,
                                                       const Px* __restrict u, int p) {
    const int s = level.stride;
    return backwardOffDiagonal(level, u, p) + level.east[p] * u[p + 1] + level.south[p] * u[p + s] +
           level.south_east[p] * u[p + s + 1] + level.south_west[p] * u[p + s - 1];
  }

  // Its part towards the neighbours before p (west, north-west, north, north-east).
  __attribute__((always_inline)) static Px backwardOffDiagonal(const CoarseLevel& level,
                                                               const Px* __restrict u, int p) {
    const int s = level.stride;
    return level.east[p - 1] * u[p - 1] + level.south[p - s] * u[p - s] +
           level.south_east[p - s - 1] * u[p - s - 1] + level.south_west[p - s + 1] * u[p - s + 1];
  }

  // backwardOffDiagonal without the west neighbour (north-west, north, north-east).
  __attribute__((always_inline)) static Px backwardOffDiagonalButWest(const CoarseLevel& level,
                                                                      const Px* __restrict u,
                                                                      int p) {
    const int s = level.stride;
    return level.south[p - s] * u[p - s] + level.south_east[p - s - 1] * u[p - s - 1] +
           level.south_west[p - s + 1] * u[p - s + 1];
  }

  // The part towards the neighbours after p (east, south-west, south, south-east).
  __attribute__((always_inline)) static Px forwardOffDiagonal(const CoarseLevel& level,
                                                              const Px* __restrict u, int p) {
    return level.east[p] * u[p + 1] + forwardOffDiagonalButEast(level, u, p);
  }

  // forwardOffDiagonal without the east neighbour.
  __attribute__((always_inline)) static Px forwardOffDiagonalButEast(const CoarseLevel& level,
                                                                     const Px* __restrict u,
                                                                     int p) {
    const int s = level.stride;
    return level.south[p] * u[p + s] + level.south_east[p] * u[p + s + 1] +
           level.south_west[p] * u[p + s - 1];
  }

  // The residual f - A u at pixel p of the finest level; without f, u holds the Dirichlet
  // values (the right-hand side). 0 at Dirichlet pixels and in the ghost border. With the
  // solution's values in u, summed as differences of neighbouring values, which are exact in
  // floating point where the values are close: a sum of four values less 4 u loses ~1e-7
  // absolute per pixel, which in a region pinned by a few pixels adds up to errors of 1e-4 in
  // the solution. A correction (with f) has small values and takes the cheaper form.
  __attribute__((always_inline)) static Px residualAt(const FineLevel& level,
                                                      const Px* __restrict u,
                                                      const Px* __restrict f, size_t p) {
    if (f) return f[p] - operatorAt(level, u, p);
    const size_t s = static_cast<size_t>(level.stride);
    const std::uint8_t m = level.mask[p];
    if (m == kAllLinks) {
      const Px centre = u[p];
      return ((u[p - 1] - centre) + (u[p + 1] - centre)) +
             ((u[p - s] - centre) + (u[p + s] - centre));
    }
    if (m & kFixed) return Px{};
    const LinkWeights& w = kWeights[m];
    return w.left * (u[p - 1] - u[p]) + w.right * (u[p + 1] - u[p]) + w.up * (u[p - s] - u[p]) +
           w.down * (u[p + s] - u[p]);
  }

  // (A v)(p) on the finest level for a field v that is 0 at Dirichlet pixels (a correction or
  // a search direction: small values, so no care for cancellation).
  __attribute__((always_inline)) static Px operatorAt(const FineLevel& level,
                                                      const Px* __restrict v, size_t p) {
    const size_t s = static_cast<size_t>(level.stride);
    const std::uint8_t m = level.mask[p];
    if (m == kAllLinks) return 4.0f * v[p] - ((v[p - 1] + v[p + 1]) + (v[p - s] + v[p + s]));
    if (m & kFixed) return Px{};
    const LinkWeights& w = kWeights[m];
    return (w.left + w.right + w.up + w.down) * v[p] -
           (w.left * v[p - 1] + w.right * v[p + 1] + w.up * v[p - s] + w.down * v[p + s]);
  }

  // On a coarse level, with the smoother's fast path for the regular stencil.
  __attribute__((always_inline)) static Px residualAt(const CoarseLevel& level,
                                                      const Px* __restrict u,
                                                      const Px* __restrict f, size_t p) {
    const int q = static_cast<int>(p);
    if (level.regular[q]) {
      const Stencil& stencil = level.regular_stencil;
      return f[q] - stencil[kC] * u[q] -
             regularOffDiagonal(u, q, level.stride, stencil[kE], stencil[kSE]);
    }
    return f[q] - level.centre[q] * u[q] - offDiagonal(level, u, q);
  }

  // Restricts the residual of level l to level l + 1 with P^T: each fine point sends its
  // residual to the coarse points its correction comes from, with the same weights.
  void restrictResidual(int l, const Px* u, const Px* f, Px* fc) const {
    if (l == 0) {
      const FineLevel& fine = fine_;
      restrictFrom(
          fine, l, [&](size_t p) { return residualAt(fine, u, f, p); }, fc);
    } else {
      // Inlined: as a call per pixel it cost as much again as the 9-point residual itself.
      const CoarseLevel& fine = coarse_[l - 1];
      const auto residual = [&](size_t p) __attribute__((always_inline)) {
        return residualAt(fine, u, f, p);
      };
      restrictFrom(fine, l, residual, fc);
    }
  }

  // P^T times the fine field residual(p) of level l into fc (level l + 1), cell by cell; a
  // cell's square sends to its own coarse row and the next, which is cleared just before. With
  // kBlackZero the residual is known to be 0 at the edge points (x + y odd).
  template <bool kBlackZero = false, class Op, class Residual>
  void restrictFrom(const Op& fine, int l, Residual&& residual, Px* __restrict fc) const {
    const CoarseLevel& coarse = coarse_[l];
    const Transfer& transfer = transfers_[l];
    const int fs = fine.stride, cs = coarse.stride;
    std::fill_n(fc, coarse.index(-1, 1), Px{});  // the ghost row above and row 0
    for (int j = 0; j < coarse.height; ++j) {
      std::fill_n(fc + coarse.index(-1, j + 1), coarse.width + 2, Px{});
      // The x-edge and y-edge points (and so the centre) of the last cells can lie outside.
      const bool y_inside = 2 * j + 1 < fine.height;
      for (int i = 0; i < coarse.width; ++i) {
        const int c = coarse.index(i, j);
        const size_t p = static_cast<size_t>(fine.index(2 * i, 2 * j));
        const CellWeights& w = transfer[c];
        const bool x_inside = 2 * i + 1 < fine.width;
        const Px r00 = residual(p);
        const Px r11 = x_inside && y_inside ? residual(p + fs + 1) : Px{};
        if constexpr (kBlackZero) {
          fc[c] += r00 + w.nw * r11;
          fc[c + 1] += w.ne * r11;
          fc[c + cs] += w.sw * r11;
        } else {
          const Px r10 = x_inside ? residual(p + 1) : Px{};
          const Px r01 = y_inside ? residual(p + fs) : Px{};
          fc[c] += r00 + w.x_west * r10 + w.y_north * r01 + w.nw * r11;
          fc[c + 1] += w.x_east * r10 + w.ne * r11;
          fc[c + cs] += w.y_south * r01 + w.sw * r11;
        }
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
    coarsest_values_.resize(static_cast<size_t>(n) * C);
  }

  // Solves the coarsest level exactly, per channel.
  void solveCoarsest(Px* u, const Px* f) {
    const int l = levelCount() - 1;
    const int w = l == 0 ? fine_.width : coarse_[l - 1].width;
    const int stride = w + 2;
    const int n = coarsest_.size();
    const auto pixel = [&](int k) { return (k / w + 1) * stride + k % w + 1; };
    const auto unknown = [&](int p) { return l == 0 ? fine_.isFree(p) : coarse_[l - 1].isFree(p); };
    // Whole pixels first: setChannel writes channels 0..C-1 only, and a 3-channel pixel has a
    // fourth (padding) lane that the vector arithmetic of every level carries along. Left as the
    // uninitialised allocation had it, it could hold denormals (freed heap's pointer bits), which
    // made the V-cycles 10x slower in about half the runs (by address layout; the image the same).
    // Level 0 as the coarsest: its Dirichlet pixels keep their values.
    for (int k = 0; k < n; ++k) {
      if (l > 0 || unknown(pixel(k))) u[pixel(k)] = Px{};
    }
    // The channels one after the other in coarsest_values_, solved together.
    const auto values = [&](int c) { return coarsest_values_.data() + static_cast<size_t>(c) * n; };
    for (int c = 0; c < C; ++c) {
      for (int k = 0; k < n; ++k) values(c)[k] = channel(f[pixel(k)], c);
    }
    if constexpr (C == 3) {
      coarsest_.solve(values(0), values(1), values(2));
    } else {
      static_assert(C == 1, "one or three channels");
      coarsest_.solve(values(0));
    }
    for (int c = 0; c < C; ++c) {
      for (int k = 0; k < n; ++k) {
        if (unknown(pixel(k))) setChannel(u[pixel(k)], c, static_cast<float>(values(c)[k]));
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
  numerics::BandedCholesky coarsest_;
  std::vector<double> coarsest_values_;
  size_t free_count_ = 0;
  std::vector<Field> u_, f_;        // per level: solution (FMG) or correction (V-cycle), rhs
  Field r_, z_, p_, ap_;            // CG: residual, preconditioned residual, direction, A direction
  Field before_last_cycle_;         // level 1 before FMG's last V-cycle there
  int next_to_finest_cycles_ = 0;   // FMG's V-cycles done on level 1
  std::vector<Px> alphas_, betas_;  // CG's step coefficients (its Lanczos matrix)
  DeflationSpace deflation_;
  cv::Mat seed_marks_, square_marks_;   // where the correction is large, and around them
  std::vector<int> singletons_;         // the deflation's singleton pieces
  bool deflating_ = false;              // this solve's CG has started deflating
  std::vector<int> seeds_;              // the start's pixels with a large residual
  LocalRelaxationSet local_;            // and the pixels around them
  double first_estimate_ = 0.0;         // of the FMG start
  std::array<double, C> ritz_floor_{};  // see errorEstimate
  Eigen::MatrixXd regions_;             // a vector over the deflation regions per channel
  std::vector<Px> coefficients_;        // per region (and 0 past the last): Z's coefficients
  // Floor of the eigenvalue the error estimate divides by (float round-off in long runs).
  static constexpr double kSmallestRitz = 1e-3;
  // Local relaxation of the start: a residual above this (colour units; the spots it is for
  // have 0.01-0.3, the rest of a converging start below 1e-3; the iteration counts of the
  // bench inputs were the same from 5e-4 to 5e-3) seeds a square of this radius; at most
  // one seed per this many free pixels.
  // Colour units: a few float ulps at 1, far below an 8-bit step (1/255).
  static constexpr double kFloatResolution = 1e-6;
  static constexpr float kLocalRelaxationResidual = 2e-3f;
  static constexpr int kLocalRelaxationRadius = 2;
  static constexpr size_t kMaxSeedShare = 16;
  // Isolated spots: at most one seed per this many free pixels (a waved glyph at 512 px has
  // up to 270 seeds, the ladybug 3,652), relaxed on squares of this radius (see
  // MultigridOptions::isolated_spot_sweeps and docs/rendering.md, session 37).
  static constexpr size_t kIsolatedSeedShare = 256;
  static constexpr int kIsolatedSpotRadius = 3;
  // Singleton pieces (see singletonPixels; measurements in docs/rendering.md, session 30). On
  // the ladybug at 512 px 0.15 picks 7,338 pixels (3 iterations instead of 6), 0.1 14,751 (3,
  // but E's factorisation costs more than they save); at 1024 px 0.15 picks 133,867 pixels,
  // 0.25 19,235 (4 iterations instead of 10); at 768 px both pick too many (0.4 would do, 4
  // iterations instead of 6 for 2 % fewer instructions, but on a fast-converging circle it
  // made the error estimate rise from one iteration to the next). At most 1/32 of the free
  // pixels: the blur field of heart_glow (512 px) had 9,454 at 0.25 and solved 3 ms slower.
  static constexpr float kSingletonShares[] = {0.15f, 0.25f};
  static constexpr int kSingletonRadius = 3;
  static constexpr size_t kMaxSingletonShare = 32;
  // E's factorisation grows faster than the pixel count (about n^1.5 for n singletons in a
  // region): the ladybug at 2048 px takes 80,362 (3 iterations instead of 6); 3072 and 4096 px
  // take none (their shares pick more than 1/32), and nothing larger than 2^17 is tried.
  static constexpr size_t kMaxSingletons = size_t{1} << 17;
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
  ConstantRegions constant;
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
      options.next_to_finest_cycles < 0 || options.max_fine_cycles < 0 || options.fine_cycles < 0 ||
      options.local_relaxation < 0 || options.isolated_spot_sweeps < 0 ||
      !(options.tolerance >= 0.0)) {
    throw std::invalid_argument("solveMultigrid: negative counts or tolerance");
  }
  if (!std::isfinite(options.extra_next_to_finest_cycle_above) ||
      options.extra_next_to_finest_cycle_above < 0.0) {
    throw std::invalid_argument(
        "solveMultigrid: extra_next_to_finest_cycle_above must be a finite number >= 0");
  }
}

}  // namespace

void MultigridSolver::solve(const GridProblem& problem, const MultigridOptions& options,
                            float* values, MultigridReport* report) {
  validate(problem, options);
  if (options.constant_regions && options.tolerance > 0.0 &&
      workspaces_->constant.solve(problem, ConstantRegions::kDefaultSpread, values)) {
    if (report) {
      *report = MultigridReport{};
      report->converged = true;
      report->constant_regions = true;
    }
    return;
  }
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
