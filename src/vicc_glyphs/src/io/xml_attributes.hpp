#pragma once
// Strict tinyxml2 document and attribute access for the XML based formats: every missing or
// malformed value becomes a FormatError that names the source, the element and the attribute.

#include <tinyxml2.h>

#include <string>

#include "vicc_glyphs/dci/diffusion_curve.hpp"

namespace vicc_glyphs {
namespace io_detail {

/// Parses `text` into `document`; throws FormatError(source, "line N", reason) on XML errors.
void parseXmlDocument(tinyxml2::XMLDocument& document, const std::string& text,
                      const std::string& source);

/// Number of non-overlapping occurrences of `needle` in `text` (cheap pre-parse size check).
std::size_t countOccurrences(const std::string& text, const std::string& needle);

/// The required attribute `name` of `element` as a finite double.
double requireDouble(const tinyxml2::XMLElement& element, const char* name,
                     const std::string& source, const std::string& place);
/// The required attribute `name` of `element` as an int.
int requireInt(const tinyxml2::XMLElement& element, const char* name, const std::string& source,
               const std::string& place);

/// "more than N control points (limit per file)", N = kMaxControlPointsPerFile.
std::string tooManyControlPointsMessage();
/// Throws FormatError when `text` holds more <control_point> elements than allowed; checked
/// before a DOM is built for a huge file.
void rejectTooManyControlPoints(const std::string& text, const std::string& source);

/// The root element of a curve file: the control-point limit checked (rejectTooManyControlPoints),
/// `text` parsed into `document`; throws FormatError(source, "root", "expected " + `expected`)
/// unless the root element is named `root_name`.
const tinyxml2::XMLElement& parseCurveFileRoot(tinyxml2::XMLDocument& document,
                                               const std::string& text, const std::string& source,
                                               const char* root_name, const std::string& expected);

/// The first child element `name` of `parent`; throws FormatError(source, place, "missing <name>").
const tinyxml2::XMLElement& requireChild(const tinyxml2::XMLElement& parent, const char* name,
                                         const std::string& source, const std::string& place);

/// The Bezier segment count of a curve just read; throws FormatError(source, place, ...) unless
/// it has 3K+1 control points (K >= 1) that are not all equal.
int requireDrawableSegments(const DiffusionCurve& curve, const std::string& source,
                            const std::string& place);

/// image_width and image_height of a curve file's root element, each within 1..100000.
void requireImageSize(const tinyxml2::XMLElement& root, const std::string& source,
                      const std::string& place, int& width, int& height);

}  // namespace io_detail
}  // namespace vicc_glyphs
