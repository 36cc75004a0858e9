#pragma once
// One entry point for every supported input: dispatches on the file extension.

#include <string>

#include "vicc_glyphs/dci/diffusion_curve.hpp"
#include "vicc_glyphs/io/format_error.hpp"
#include "vicc_glyphs/io/svg_import.hpp"

namespace vicc_glyphs {

/// Loads .xml (Orzan), .svg or .png (case-insensitive). `size` > 0 scales the result to that
/// width (SVG: at import; others: scaledToWidth). The result always passes validate().
/// Throws FormatError for unknown extensions, unreadable files and invalid results.
DiffusionCurveImage loadDiffusionCurves(const std::string& path, int size = 0);
/// The same with the SVG import options (their `size` is replaced by `size`).
DiffusionCurveImage loadDiffusionCurves(const std::string& path, int size,
                                        const SvgImportOptions& svg);

}  // namespace vicc_glyphs
