// Writer of Orzan's XML format (conventions in orzan_conventions.hpp). Numbers are printed in
// their shortest round-trip form, so reading the output back gives the same doubles (colours up
// to the 255 scaling).

#include <array>
#include <charconv>
#include <sstream>

#include "orzan_conventions.hpp"
#include "text_file.hpp"
#include "vicc_glyphs/io/orzan_xml.hpp"

namespace vicc_glyphs {
namespace {

std::string number(double value) {
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return std::string(buffer.data(), result.ptr);
}

std::string attribute(const char* name, double value) {
  return std::string(" ") + name + "=\"" + number(value) + "\"";
}

void writeColors(std::ostringstream& out, const char* set, const char* element,
                 const std::vector<ColorPoint>& colors, bool emits) {
  out << "  <" << set
      << (emits ? "" : std::string(" boundary=\"") + io_detail::kBarrierBoundary + "\"") << ">\n";
  for (const ColorPoint& c : colors) {
    // Attribute order as in the published files: G, R, globalID, B; R/B labels swapped.
    out << "   <" << element << attribute("G", c.rgb[1] * io_detail::kColorScale)
        << attribute("R", c.rgb[2] * io_detail::kColorScale)
        << attribute("globalID", c.position * io_detail::kGlobalIdPerSegment)
        << attribute("B", c.rgb[0] * io_detail::kColorScale) << "/>\n";
  }
  out << "  </" << set << ">\n";
}

}  // namespace

std::string formatOrzanXml(const DiffusionCurveImage& image) {
  const std::string problem = validate(image);
  if (!problem.empty()) throw FormatError("<image>", "", "cannot write invalid image: " + problem);
  std::ostringstream out;
  out << "<!DOCTYPE CurveSetXML>\n";
  out << "<curve_set image_width=\"" << image.width << "\" image_height=\"" << image.height
      << "\" nb_curves=\"" << image.curves.size() << "\">\n";
  for (const DiffusionCurve& curve : image.curves) {
    // The file's left side is our left side (see orzan_conventions.hpp).
    out << " <curve nb_control_points=\"" << curve.control_points.size() << "\" nb_left_colors=\""
        << curve.left_colors.size() << "\" nb_right_colors=\"" << curve.right_colors.size()
        << "\" nb_blur_points=\"" << curve.blur_points.size() << "\" lifetime=\"32\">\n";
    out << "  <control_points_set>\n";
    for (const Point2& p : curve.control_points) {
      out << "   <control_point" << attribute("x", p.y()) << attribute("y", p.x()) << "/>\n";
    }
    out << "  </control_points_set>\n";
    writeColors(out, "left_colors_set", "left_color", curve.left_colors, curve.left_emits);
    writeColors(out, "right_colors_set", "right_color", curve.right_colors, curve.right_emits);
    out << "  <blur_points_set>\n";
    for (const BlurPoint& b : curve.blur_points) {
      out << "   <best_scale" << attribute("value", b.sigma)
          << attribute("globalID", b.position * io_detail::kGlobalIdPerSegment) << "/>\n";
    }
    out << "  </blur_points_set>\n";
    out << " </curve>\n";
  }
  out << "</curve_set>\n";
  return out.str();
}

void writeOrzanXml(const DiffusionCurveImage& image, const std::string& path) {
  io_detail::writeTextFile(path, formatOrzanXml(image));
}

}  // namespace vicc_glyphs
