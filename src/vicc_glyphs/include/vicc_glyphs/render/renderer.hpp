#pragma once
// Renders a DiffusionCurveImage to an RGB raster (Orzan et al. 2008): colour constraints on
// both sides of each curve, Laplace diffusion by full multigrid (Galerkin coarse operators,
// multigrid-preconditioned conjugate gradients), anti-aliasing along the curves, optional blur
// pass.

#include <memory>
#include <opencv2/core.hpp>
#include <string>

#include "vicc_glyphs/dci/diffusion_curve.hpp"
#include "vicc_glyphs/render/multigrid.hpp"

namespace vicc_glyphs {

/// Largest image one render may have (width x height, after RenderOptions::size): the
/// multigrid hierarchy needs ~100-200 bytes per pixel, so 16.8 M pixels stay within ~3 GB.
constexpr double kMaxRenderPixels = 4096.0 * 4096.0;

struct RenderOptions {
  int size = 0;               ///< output width; 0 = the image's own width
  Color background{0, 0, 0};  ///< colour of regions no curve colours (see grid_problem.hpp)
  bool antialias = true;      ///< blend the two sides along the curves by coverage
  bool blur = true;           ///< run the blur pass when some curve has blur points
  MultigridOptions multigrid;
};

struct RenderTimings {
  double assemble_ms = 0.0;  ///< rasterising the constraints on all levels
  double solve_ms = 0.0;     ///< multigrid
  double antialias_ms = 0.0;
  double blur_ms = 0.0;  ///< blur field solve and variable blur
  double total_ms = 0.0;
};

struct RenderReport {
  MultigridReport multigrid;
  RenderTimings timings;
  bool blurred = false;
  /// Pixels whose colour a curve set (GridProblem::curve_pixels); 0: the picture is only the
  /// background, which tools must not pass off as a rendering (see requireSomethingDrawn).
  int curve_pixels = 0;
};

/// Throws std::runtime_error naming `what` when `report` says that no curve with colours
/// reached the image (a uniform background picture: an empty or unreadable input, curves
/// outside the frame or without colours, a glyph too small to cross a pixel).
void requireSomethingDrawn(const RenderReport& report, const std::string& what);

struct RenderResult {
  cv::Mat image;     ///< CV_32FC3, RGB in [0, 1]: the final picture
  cv::Mat diffused;  ///< CV_32FC3, RGB: the multigrid solution before anti-aliasing and blur
  RenderReport report;
};

/// Renders images, keeping all working memory (grids, multigrid levels, output Mats when
/// `result` is reused) between calls: a long-running node or the bench renders repeatedly,
/// and fresh memory costs page faults that can take longer than the diffusion itself.
class DiffusionCurveRenderer {
 public:
  DiffusionCurveRenderer();
  ~DiffusionCurveRenderer();
  DiffusionCurveRenderer(const DiffusionCurveRenderer&) = delete;
  DiffusionCurveRenderer& operator=(const DiffusionCurveRenderer&) = delete;

  /// Renders `image` (scaled to options.size if set) into `result`. An image without pixels
  /// gives empty Mats; curves with bad point counts or no length are ignored. Throws
  /// std::length_error for more than kMaxRenderPixels pixels.
  void render(const DiffusionCurveImage& image, const RenderOptions& options, RenderResult& result);

 private:
  struct Workspace;
  std::unique_ptr<Workspace> workspace_;
};

/// One-off render with a temporary DiffusionCurveRenderer.
RenderResult renderDiffusionCurves(const DiffusionCurveImage& image,
                                   const RenderOptions& options = {});

/// Copies pixel-major float values (width*height*channels) into `mat` (CV_32FC(channels)).
void valuesToMat(const std::vector<float>& values, int width, int height, int channels,
                 cv::Mat& mat);

}  // namespace vicc_glyphs
