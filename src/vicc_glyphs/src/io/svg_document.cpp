#include "svg_document.hpp"

#include <tinyxml2.h>

#include <cmath>
#include <set>
#include <stdexcept>

#include "svg_number_scanner.hpp"
#include "svg_path_data.hpp"
#include "svg_shapes.hpp"
#include "svg_style.hpp"
#include "svg_transform.hpp"
#include "xml_attributes.hpp"

namespace vicc_glyphs {
namespace io_detail {
namespace {

using tinyxml2::XMLElement;

constexpr int kMaxDepth = 256;
constexpr double kMaxImageSide = 100000.0;

// Containers whose content is not painted directly (or is painted only by reference).
const std::set<std::string>& unpaintedContainers() {
  static const std::set<std::string> names = {
      "defs",           "clipPath", "mask",  "symbol", "marker",   "pattern", "linearGradient",
      "radialGradient", "style",    "title", "desc",   "metadata", "text",    "foreignObject"};
  return names;
}

class SvgWalker {
 public:
  SvgWalker(std::string source, const SvgImportOptions& options)
      : source_(std::move(source)), options_(options), budget_(kMaxControlPointsPerFile) {}

  SvgPicture read(const std::string& text) {
    tinyxml2::XMLDocument document;
    parseXmlDocument(document, text, source_);
    const XMLElement* root = document.RootElement();
    if (!root || std::string(root->Name()) != "svg") {
      throw FormatError(source_, "root", "expected an <svg> root element");
    }
    SvgPicture picture;
    picture.scene = PaintedScene(options_.background);
    const Affine2 viewport = guarded(*root, [&] { return setupViewport(*root, picture); });
    walk(*root, viewport, SvgStyle{}, 0, picture);
    return picture;
  }

 private:
  std::string place(const XMLElement& e) const {
    return "<" + std::string(e.Name()) + "> line " + std::to_string(e.GetLineNum());
  }

  // Runs `step`, turning the helpers' exceptions into FormatErrors that name the element.
  template <typename Step>
  auto guarded(const XMLElement& element, Step step) -> decltype(step()) {
    try {
      return step();
    } catch (const std::invalid_argument& e) {
      throw FormatError(source_, place(element), e.what());
    } catch (const std::length_error& e) {
      throw FormatError(source_, place(element), e.what());
    }
  }

  // Maps the viewBox (or 0 0 width height) to pixels; with options.size > 0 the width becomes
  // that many pixels. preserveAspectRatio is not needed: the image takes the viewBox's aspect.
  Affine2 setupViewport(const XMLElement& root, SvgPicture& picture) const {
    double x = 0.0, y = 0.0, w = 0.0, h = 0.0;
    if (const char* view_box = root.Attribute("viewBox")) {
      const std::string text(view_box);
      SvgNumberScanner scanner(text);
      x = scanner.number();
      y = scanner.number();
      w = scanner.number();
      h = scanner.number();
      if (!scanner.atEnd()) throw std::invalid_argument("viewBox needs exactly 4 numbers");
    } else {
      w = svgLength(root, "width", 0.0);
      h = svgLength(root, "height", 0.0);
    }
    if (!(w > 0.0) || !(h > 0.0)) {
      throw std::invalid_argument("no positive size: need viewBox or width and height");
    }
    const double scale = options_.size > 0 ? options_.size / w : 1.0;
    const double width = std::ceil(w * scale - 1e-9);
    const double height = std::ceil(h * scale - 1e-9);
    if (width > kMaxImageSide || height > kMaxImageSide || !(width >= 1.0) || !(height >= 1.0)) {
      throw std::invalid_argument("image size outside 1.." +
                                  std::to_string(static_cast<int>(kMaxImageSide)) + " pixels");
    }
    picture.width = static_cast<int>(width);
    picture.height = static_cast<int>(height);
    Affine2 viewport = Affine2::Identity();
    viewport.scale(scale).translate(Eigen::Vector2d(-x, -y));
    return viewport;
  }

  void walk(const XMLElement& element, const Affine2& parent_transform,
            const SvgStyle& parent_style, int depth, SvgPicture& picture) {
    if (depth > kMaxDepth) throw FormatError(source_, place(element), "nesting too deep");
    const std::string name = element.Name();
    if (unpaintedContainers().count(name)) return;
    const SvgStyle style = guarded(element, [&] { return cascadeStyle(element, parent_style); });
    if (!style.displayed) return;
    Affine2 transform = parent_transform;
    if (const char* attribute = element.Attribute("transform")) {
      transform = parent_transform * guarded(element, [&] { return parseSvgTransform(attribute); });
    }
    if (name == "path" || isBasicShape(name)) {
      addShape(element, name, transform, style, picture);
      return;
    }
    if (name != "svg" && name != "g" && name != "a" && name != "switch") return;
    for (const XMLElement* child = element.FirstChildElement(); child;
         child = child->NextSiblingElement()) {
      walk(*child, transform, style, depth + 1, picture);
    }
  }

  void addShape(const XMLElement& element, const std::string& name, const Affine2& transform,
                const SvgStyle& style, SvgPicture& picture) {
    std::vector<Contour> contours = guarded(element, [&] {
      if (name != "path") return basicShapeContours(element, budget_);
      const char* d = element.Attribute("d");
      if (!d) throw std::invalid_argument("missing attribute d");
      return parseSvgPathData(d, budget_);
    });
    if (!style.fill || !style.visible || contours.empty()) return;
    for (Contour& contour : contours) {
      for (Point2& p : contour) p = transform * p;
    }
    picture.scene.addShape(std::move(contours), *style.fill, style.rule);
  }

  std::string source_;
  SvgImportOptions options_;
  PointBudget budget_;
};

}  // namespace

SvgPicture readSvgPicture(const std::string& text, const std::string& source,
                          const SvgImportOptions& options) {
  return SvgWalker(source, options).read(text);
}

}  // namespace io_detail
}  // namespace vicc_glyphs
