#pragma once
// Orzan et al.'s diffusion curve XML format (the files of their drawing tool and published
// samples): <curve_set image_width= image_height=> with <curve> elements holding
// <control_points_set>, <left_colors_set>, <right_colors_set> and <blur_points_set>.
// Conventions of the format, converted here to ours (diffusion_curve.hpp):
// - control points store x and y swapped relative to image coordinates (file x = our y);
// - colours are stored as B, G, R in 0..255 (ours: RGB in [0, 1]);
// - colour and blur points carry globalID in 0..10*K along the curve (ours: s = globalID / 10).

#include <string>

#include "vicc_glyphs/dci/diffusion_curve.hpp"
#include "vicc_glyphs/io/format_error.hpp"

namespace vicc_glyphs {

/// Reads and validates an Orzan XML file. Throws FormatError.
DiffusionCurveImage readOrzanXml(const std::string& path);
/// Parses Orzan XML text. Throws FormatError (source "<string>").
DiffusionCurveImage parseOrzanXml(const std::string& text);

/// Writes `image` as Orzan XML (throws FormatError if the file cannot be written or the image
/// is invalid).
void writeOrzanXml(const DiffusionCurveImage& image, const std::string& path);
/// Formats `image` as Orzan XML text; read back it gives the same image up to the printed
/// precision (colours are stored as fractional 0..255 values, so no quantisation).
std::string formatOrzanXml(const DiffusionCurveImage& image);

}  // namespace vicc_glyphs
