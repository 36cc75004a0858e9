#pragma once
// The SceneXML format of small-usvg (Tian and Guenther, MIT; github.com/tobguent/small-usvg,
// usvg/src/scene.cpp): <!DOCTYPE SceneXML>, root <scene image_width= image_height=> holding a
// <curve_set nb_curves=> of <curve> elements with <control_points_set>, <left_colors_set> and
// <right_colors_set> (element names as in Orzan's CurveSetXML). Conventions, converted to ours
// (diffusion_curve.hpp):
// - control point x, y are image coordinates as they are (x right, y down; no x/y swap);
// - colours are R, G, B in 0..255, or lowercase r, g, b in 0..1 (no R/B swap);
// - the file's left colours lie on the (-dy, dx) side of the tangent (dx, dy), i.e. on OUR
//   right side, so the sides are exchanged on reading;
// - globalID is normalised by the largest globalID of its colour set when that exceeds 1 (else
//   taken as is) and the result in [0, 1] spans the whole curve: s = K * globalID / max;
// - boundary="Neumann" on a colour set makes that side a diffusion barrier (emits = false);
// - nb_curves, nb_control_points, nb_left_colors, nb_right_colors say how many child elements
//   small-usvg reads: fewer present is an error here, extra ones are ignored as there.
// Not read: <poisson_curve_set> and <mesh_set> (Poisson curves, gradient meshes) have no
// counterpart in our representation and are skipped, so scenes using them (the ladybug's sky
// and leaf fill) render without those parts; <blur_points_set> is ignored, as by small-usvg.

#include <string>

#include "vicc_glyphs/dci/diffusion_curve.hpp"
#include "vicc_glyphs/io/format_error.hpp"

namespace vicc_glyphs {

/// Reads and validates a SceneXML file. Throws FormatError.
DiffusionCurveImage readUsvgSceneXml(const std::string& path);
/// Parses SceneXML text; `source` names it in error messages. Throws FormatError.
DiffusionCurveImage parseUsvgSceneXml(const std::string& text,
                                      const std::string& source = "<string>");
/// True if the first element of `text` is <scene> (SceneXML), judged without building a DOM.
bool hasUsvgSceneRoot(const std::string& text);

}  // namespace vicc_glyphs
