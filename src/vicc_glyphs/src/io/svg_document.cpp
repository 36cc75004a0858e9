#include "svg_document.hpp"

#include <tinyxml2.h>

#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>

#include "curve_stroke.hpp"
#include "svg_paint_server.hpp"
#include "svg_path_data.hpp"
#include "svg_shapes.hpp"
#include "svg_style.hpp"
#include "svg_transform.hpp"
#include "svg_viewport.hpp"
#include "xml_attributes.hpp"

namespace vicc_glyphs {
namespace io_detail {
namespace {

using tinyxml2::XMLElement;

// Element nesting plus <use> indirections; below tinyxml2's own limit of 100 nested elements.
constexpr int kMaxDepth = 64;
constexpr std::size_t kMaxPolygonVertices = 200000;
// Canvas margin in pixels: region boundaries along the image border lie outside the image.
constexpr double kCanvasMargin = 2.0;
// Painted areas lose gaps and parts narrower than twice this (pixels): see withoutSubpixelDetail.
constexpr double kSubpixelRadius = 0.25;
// Region boundaries lose spikes (out and back along one line) up to this wide (px).
constexpr double kSpikeWidth = 0.001;

// Containers whose content is not painted directly (or is painted only by reference).
const std::set<std::string>& unpaintedElements() {
  static const std::set<std::string> names = {
      "defs",           "clipPath", "mask",  "symbol", "marker",   "pattern", "linearGradient",
      "radialGradient", "style",    "title", "desc",   "metadata", "filter",  "script"};
  return names;
}

// Elements that paint something this importer cannot represent.
const std::set<std::string>& unsupportedElements() {
  static const std::set<std::string> names = {"text",   "image",  "foreignObject", "video",
                                              "canvas", "iframe", "audio"};
  return names;
}

class SvgWalker {
 public:
  SvgWalker(std::string source, const SvgImportOptions& options)
      : source_(std::move(source)),
        options_(options),
        budget_(kMaxControlPointsPerFile),
        vertices_(kMaxPolygonVertices) {}

  SvgPicture read(const std::string& text) {
    tinyxml2::XMLDocument document;
    parseXmlDocument(document, text, source_);
    const XMLElement* root = document.RootElement();
    if (!root || std::string(root->Name()) != "svg") {
      throw FormatError(source_, "root", "expected an <svg> root element");
    }
    collect(*root);
    SvgPicture picture;
    const SvgViewport viewport = guarded(*root, [&] { return svgViewport(*root, options_.size); });
    picture.width = viewport.width;
    picture.height = viewport.height;
    frame_ = IntegerFrame(picture.width, picture.height);
    picture.frame = frame_;
    // Flattening error small against a pixel at any size up to ~8000 px.
    tolerance_ = std::max(picture.width, picture.height) / 8192.0;
    SvgStyle initial;
    initial.color = options_.current_color;
    PaintMap map;
    walk(*root, viewport.user_to_pixels, initial, 0, map);
    const Paths canvas = {rectangle(frame_, -kCanvasMargin, -kCanvasMargin,
                                    picture.width + kCanvasMargin, picture.height + kCanvasMargin)};
    picture.resolved = map.resolve(options_.background, canvas);
    for (ColorRegion& region : picture.resolved.regions) region.area = tidied(region.area);
    picture.resolved.background.area = tidied(picture.resolved.background.area);
    return picture;
  }

 private:
  // A resolved area's boundary as the curves need it. Strictly simple: where shapes of one
  // colour touch (a line tangent to a ring's inner edge), Clipper's union can join a hole to
  // the outer boundary by a slit of two coincident edges through the region; a curve along it
  // has the region's colour on both sides, but the side colour is sampled at a point that lies
  // on the slit's other edge and reads as the background (a streak of dots, Feather `chrome`).
  // Then without spikes (see withoutSpikes).
  Paths tidied(const Paths& area) const {
    return withoutSpikes(simplified(area, FillRule::kNonZero),
                         kSpikeWidth * frame_.unitsPerPixel());
  }

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

  // Strict: an error naming the feature. Lenient: a warning, and the caller leaves it out.
  void unsupported(const XMLElement& element, const std::string& feature) {
    if (!options_.lenient)
      throw FormatError(source_, place(element), feature + " is not supported");
    if (options_.warn)
      options_.warn(source_ + ": " + place(element) + ": " + feature +
                    " is not supported; ignored");
  }

  // Ids for <use>, clip-path and paint references; the text of every <style> element.
  void collect(const XMLElement& element) {
    if (const char* id = element.Attribute("id")) ids_.emplace(id, &element);
    if (std::string(element.Name()) == "style") {
      std::string css;
      for (const tinyxml2::XMLNode* node = element.FirstChild(); node; node = node->NextSibling()) {
        if (const tinyxml2::XMLText* text = node->ToText()) css += text->Value();
      }
      guarded(element, [&] {
        sheet_.parse(css, [&](const std::string& feature) { unsupported(element, feature); });
      });
    }
    for (const XMLElement* child = element.FirstChildElement(); child;
         child = child->NextSiblingElement()) {
      collect(*child);
    }
  }

  const XMLElement* referenced(const XMLElement& from, const std::string& id) {
    const auto found = ids_.find(id);
    if (found == ids_.end())
      throw FormatError(source_, place(from), "no element with id '" + id + "'");
    return found->second;
  }

  void walk(const XMLElement& element, const Affine2& parent_transform,
            const SvgStyle& parent_style, int depth, PaintMap& target) {
    if (depth > kMaxDepth) {
      throw FormatError(source_, place(element),
                        "nested deeper than " + std::to_string(kMaxDepth) +
                            " levels (elements and <use> references)");
    }
    const std::string name = element.Name();
    if (unpaintedElements().count(name)) return;
    if (unsupportedElements().count(name)) return unsupported(element, "<" + name + ">");
    const SvgStyle style =
        guarded(element, [&] { return cascadeStyle(element, parent_style, sheet_); });
    if (!style.displayed) return;
    Affine2 transform = parent_transform;
    if (const char* attribute = element.Attribute("transform")) {
      transform = parent_transform * guarded(element, [&] { return parseSvgTransform(attribute); });
    }
    if (!style.mask.empty()) unsupported(element, "mask (" + style.mask + ")");
    if (!style.unsupported.empty()) unsupported(element, "property '" + style.unsupported + "'");
    if (!style.filter.empty()) unsupported(element, "filter (" + style.filter + ")");
    std::optional<Paths> clip;
    if (!style.clip_path.empty()) clip = clipArea(element, style.clip_path, transform, depth);
    if (style.opacity >= 1.0 && !clip) {
      paintContent(element, name, transform, style, depth, target);
      return;
    }
    PaintMap layer;
    paintContent(element, name, transform, style, depth, layer);
    target.composite(layer, style.opacity, clip ? &*clip : nullptr);
  }

  void paintContent(const XMLElement& element, const std::string& name, const Affine2& transform,
                    const SvgStyle& style, int depth, PaintMap& target) {
    if (name == "path" || isBasicShape(name))
      return paintShape(element, name, transform, style, target);
    if (name == "use") return paintUse(element, transform, style, depth, target);
    if (name == "svg" && depth > 0 && hasViewport(element)) {
      return unsupported(element, "nested <svg> with its own viewport");
    }
    if (name != "svg" && name != "g" && name != "a" && name != "switch") return;
    for (const XMLElement* child = element.FirstChildElement(); child;
         child = child->NextSiblingElement()) {
      walk(*child, transform, style, depth + 1, target);
      if (name == "switch") break;  // no conditions are evaluated: the first child is chosen
    }
  }

  static bool hasViewport(const XMLElement& element) {
    for (const char* name : {"viewBox", "x", "y", "width", "height"}) {
      if (element.Attribute(name)) return true;
    }
    return false;
  }

  void paintUse(const XMLElement& use, const Affine2& transform, const SvgStyle& style, int depth,
                PaintMap& target) {
    const char* href = use.Attribute("href");
    if (!href) href = use.Attribute("xlink:href");
    if (!href || href[0] != '#') {
      throw FormatError(source_, place(use), "<use> needs a local href=\"#id\"");
    }
    const XMLElement* target_element = referenced(use, href + 1);
    if (!active_uses_.insert(target_element).second) {
      throw FormatError(source_, place(use), std::string("circular <use> of '") + href + "'");
    }
    Affine2 placed = transform;
    placed.translate(Eigen::Vector2d(guarded(use, [&] { return svgLength(use, "x", 0.0); }),
                                     guarded(use, [&] { return svgLength(use, "y", 0.0); })));
    if (std::string(target_element->Name()) == "symbol") {
      if (hasViewport(*target_element)) {
        unsupported(*target_element, "<symbol> with its own viewport");
      }
      const SvgStyle symbol_style =
          guarded(*target_element, [&] { return cascadeStyle(*target_element, style, sheet_); });
      for (const XMLElement* child = target_element->FirstChildElement(); child;
           child = child->NextSiblingElement()) {
        walk(*child, placed, symbol_style, depth + 2, target);
      }
    } else {
      walk(*target_element, placed, style, depth + 1, target);
    }
    active_uses_.erase(target_element);
  }

  std::vector<Subpath> subpathsOf(const XMLElement& element, const std::string& name) {
    return guarded(element, [&] {
      if (name != "path") return basicShapeSubpaths(element, budget_);
      const char* d = element.Attribute("d");
      if (!d) throw std::invalid_argument("missing attribute d");
      return parseSvgPathSubpaths(d, budget_);
    });
  }

  std::vector<Subpath> transformed(std::vector<Subpath> subpaths, const Affine2& transform) {
    for (Subpath& subpath : subpaths) {
      for (Point2& p : subpath.points) p = transform * p;
    }
    return subpaths;
  }

  std::optional<Color> resolvePaint(const XMLElement& element, const SvgPaint& paint,
                                    const SvgStyle& style) {
    if (paint.kind != SvgPaint::Kind::kReference) return paintColor(paint, style);
    const XMLElement* server = referenced(element, paint.reference);
    const std::optional<Color> mean = guarded(*server, [&] {
      return gradientMeanColor(*server,
                               [&](const std::string& id) { return referenced(*server, id); });
    });
    unsupported(element, "paint server url(#" + paint.reference + ") (<" + server->Name() +
                             ">; lenient: its mean stop colour)");
    return mean;
  }

  void paintShape(const XMLElement& element, const std::string& name, const Affine2& transform,
                  const SvgStyle& style, PaintMap& target) {
    const std::vector<Subpath> subpaths = subpathsOf(element, name);
    if (!style.visible || subpaths.empty()) return;
    if (const std::optional<Color> fill = resolvePaint(element, style.fill, style)) {
      const Paths area = guarded(element, [&] {
        return fillArea(transformed(subpaths, transform), style.rule, frame_, tolerance_,
                        vertices_);
      });
      target.paint(withoutSubpixelDetail(area, frame_, kSubpixelRadius), *fill, style.fill_opacity);
    }
    if (const std::optional<Color> stroke = resolvePaint(element, style.stroke, style)) {
      const Paths area = guarded(element, [&] {
        const auto outliner =
            options_.stroke_outliner == StrokeOutliner::kCurves ? curveStrokeArea : strokeArea;
        return outliner(subpaths, transform, style.stroke_geometry, frame_, tolerance_, vertices_);
      });
      target.paint(withoutSubpixelDetail(area, frame_, kSubpixelRadius), *stroke,
                   style.stroke_opacity);
    }
  }

  // The clip region of clip-path="url(#id)" in pixels: the union of its children's fills
  // (clip-rule), in the user space of the referencing element. nullopt: ignored (lenient).
  std::optional<Paths> clipArea(const XMLElement& element, const std::string& id,
                                const Affine2& transform, int depth) {
    const XMLElement* clip_path = referenced(element, id);
    if (std::string(clip_path->Name()) != "clipPath") {
      throw FormatError(source_, place(element), "clip-path url(#" + id + ") is no <clipPath>");
    }
    const char* units = clip_path->Attribute("clipPathUnits");
    if (units && std::string(units) == "objectBoundingBox") {
      unsupported(*clip_path, "clipPathUnits=\"objectBoundingBox\"");
      return std::nullopt;
    }
    const SvgStyle base =
        guarded(*clip_path, [&] { return cascadeStyle(*clip_path, SvgStyle{}, sheet_); });
    if (!base.clip_path.empty()) {
      unsupported(*clip_path, "clip-path on a <clipPath>");
      return std::nullopt;
    }
    Affine2 clip_transform = transform;
    if (const char* attribute = clip_path->Attribute("transform")) {
      clip_transform =
          transform * guarded(*clip_path, [&] { return parseSvgTransform(attribute); });
    }
    Paths area;
    for (const XMLElement* child = clip_path->FirstChildElement(); child;
         child = child->NextSiblingElement()) {
      area = unite(area, clipChildArea(*child, clip_transform, base, depth + 1));
    }
    return area;
  }

  Paths clipChildArea(const XMLElement& child, Affine2 transform, const SvgStyle& base, int depth) {
    if (depth > kMaxDepth) throw FormatError(source_, place(child), "nested too deep");
    std::string name = child.Name();
    if (unsupportedElements().count(name)) {
      unsupported(child, "<" + name + "> in a <clipPath>");
      return {};
    }
    const SvgStyle style = guarded(child, [&] { return cascadeStyle(child, base, sheet_); });
    if (!style.displayed || !style.visible) return {};
    if (const char* attribute = child.Attribute("transform")) {
      transform = transform * guarded(child, [&] { return parseSvgTransform(attribute); });
    }
    if (name == "use") {
      const char* href = child.Attribute("href");
      if (!href) href = child.Attribute("xlink:href");
      if (!href || href[0] != '#')
        throw FormatError(source_, place(child), "<use> needs href=\"#id\"");
      transform.translate(
          Eigen::Vector2d(guarded(child, [&] { return svgLength(child, "x", 0.0); }),
                          guarded(child, [&] { return svgLength(child, "y", 0.0); })));
      return clipChildArea(*referenced(child, href + 1), transform, style, depth + 1);
    }
    if (name != "path" && !isBasicShape(name)) return {};
    return guarded(child, [&] {
      return fillArea(transformed(subpathsOf(child, name), transform), style.clip_rule, frame_,
                      tolerance_, vertices_);
    });
  }

  std::string source_;
  SvgImportOptions options_;
  PointBudget budget_;
  VertexBudget vertices_;
  IntegerFrame frame_;
  double tolerance_ = 0.01;
  StyleSheet sheet_;
  std::map<std::string, const XMLElement*> ids_;
  std::set<const XMLElement*> active_uses_;
};

}  // namespace

SvgPicture readSvgPicture(const std::string& text, const std::string& source,
                          const SvgImportOptions& options) {
  return SvgWalker(source, options).read(text);
}

}  // namespace io_detail
}  // namespace vicc_glyphs
