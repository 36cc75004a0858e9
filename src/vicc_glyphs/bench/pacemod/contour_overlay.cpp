#include "contour_overlay.hpp"

#include <fstream>

#include "vicc_glyphs/bspline/arc_length.hpp"
#include "vicc_glyphs/bspline/spline_diffusion_curve.hpp"
#include "vicc_glyphs/pacemod/polyline.hpp"
#include "vicc_glyphs/pacemod/wave_layout.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace measure {
namespace {

void polyline(std::ofstream& out, const Polyline& line, const char* colour, double width) {
  out << "<polyline fill='none' stroke='" << colour << "' stroke-width='" << width << "' points='";
  for (const Point2& p : line) out << p.x() << ',' << p.y() << ' ';
  out << "'/>\n";
}

}  // namespace

bool writeContourOverlay(const std::string& path, const DiffusionCurveImage& original,
                         const DiffusionCurveImage& modified,
                         const std::vector<CurveWaveReport>& reports, const WaveSpec& spec,
                         double px_per_mm, const std::vector<std::string>& notes,
                         const std::vector<Point2>& marks) {
  std::ofstream out(path);
  if (!out) return false;
  out << "<svg xmlns='http://www.w3.org/2000/svg' width='" << 4 * original.width << "' height='"
      << 4 * original.height << "' viewBox='0 0 " << original.width << ' ' << original.height
      << "'>\n<rect width='100%' height='100%' fill='white'/>\n";
  for (const DiffusionCurve& curve : original.curves) {
    polyline(out, sampleCurve(curve, 32), "#999", 0.15);
  }
  for (const DiffusionCurve& curve : modified.curves) {
    polyline(out, sampleCurve(curve, 16), "#d00", 0.1);
  }
  for (const CurveWaveReport& report : reports) {
    if (report.wave_count < 1) continue;
    const bspline::SplineDiffusionCurve spline =
        bspline::toSplineDiffusionCurve(original.curves[report.curve]);
    const bspline::ArcLengthTable table(spline.geometry);
    const WaveLayout layout = waveLayout(spec.waveform, report.wave_count, table.totalLength());
    for (const WavePeak& peak : layout.peaks) {
      const Point2 k = spline.geometry.pointAt(table.parameterAt(peak.arc_length));
      bool reduced = false;
      for (const PeakReduction& r : report.reductions) {
        reduced |= std::abs(r.arc_length_mm * px_per_mm - peak.arc_length) < 1e-6;
      }
      out << "<circle cx='" << k.x() << "' cy='" << k.y() << "' r='0.25' fill='"
          << (reduced ? "orange" : (peak.sign > 0 ? "blue" : "green")) << "'/>\n";
    }
    const Point2 start = spline.geometry.pointAt(0.0);
    out << "<text x='" << start.x() << "' y='" << start.y() << "' font-size='3' fill='purple'>c"
        << report.curve << "</text>\n";
  }
  for (const Point2& m : marks) {
    out << "<circle cx='" << m.x() << "' cy='" << m.y()
        << "' r='2' fill='none' stroke='magenta' stroke-width='0.2'/>\n";
  }
  double y = 4;
  for (const std::string& note : notes) {
    out << "<text x='1' y='" << y << "' font-size='2.5' font-family='monospace'>" << note
        << "</text>\n";
    y += 3;
  }
  out << "</svg>\n";
  return static_cast<bool>(out);
}

}  // namespace measure
}  // namespace pacemod
}  // namespace vicc_glyphs
