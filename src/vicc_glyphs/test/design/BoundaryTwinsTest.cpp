// One curve per region boundary: the hole a region leaves in another is dropped when it only
// repeats the inner region's outline, and kept when the colours along it change.
#include <gtest/gtest.h>

#include "../../src/design/boundary_twins.hpp"
#include "shipped_designs.hpp"
#include "vicc_glyphs/design/design_builder.hpp"
#include "vicc_glyphs/io/svg_import.hpp"

using namespace vicc_glyphs;
using namespace vicc_glyphs::design;

namespace {

DiffusionCurveImage imported(const std::string& shapes, int size) {
  SvgImportOptions options;
  options.size = size;
  return parseSvg(
      "<svg xmlns='http://www.w3.org/2000/svg' viewBox='0 0 20 20'>" + shapes + "</svg>", options);
}

}  // namespace

TEST(BoundaryTwins, DropsTheHoleThatRepeatsAnInnerOutline) {
  DiffusionCurveImage image = imported(
      "<rect x='2' y='2' width='16' height='16' fill='#808080'/>"
      "<rect x='6' y='6' width='8' height='8' fill='#ff0000'/>",
      64);
  ASSERT_EQ(image.curves.size(), 3u);  // grey outline, grey's hole, red outline
  EXPECT_EQ(removeBoundaryTwins(image), 1);
  ASSERT_EQ(image.curves.size(), 2u);
  // The red outline stays, with red on its left (its region) and grey across.
  const DiffusionCurve& red = image.curves[1];
  EXPECT_LT((red.leftColorAt(0.5) - Color(1, 0, 0)).norm(), 1e-3);
  EXPECT_LT((red.rightColorAt(0.5) - Color(0x80, 0x80, 0x80) / 255.0).norm(), 1e-3);
}

TEST(BoundaryTwins, KeepsAHoleWithSeveralColoursAcross) {
  DiffusionCurveImage image = imported(
      "<rect x='2' y='2' width='16' height='16' fill='#808080'/>"
      "<rect x='6' y='6' width='4' height='8' fill='#ff0000'/>"
      "<rect x='10' y='6' width='4' height='8' fill='#0000ff'/>",
      64);
  const size_t before = image.curves.size();
  EXPECT_EQ(removeBoundaryTwins(image), 0);
  EXPECT_EQ(image.curves.size(), before);
}

TEST(BoundaryTwins, HeadBrainIconHasTwoCurvesAtEverySize) {
  const GlyphDesign design = test::shipped("intracranial_pressure");
  for (int size : {32, 48, 160, 512}) {
    EXPECT_EQ(loadIcon(design, size).curves.size(), 2u) << size;
  }
}
