// Building the shipped designs: the encodings change the curves they name and only those.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "../../src/design/gradient_channels.hpp"
#include "../support/straight_chain.hpp"
#include "shipped_designs.hpp"
#include "vicc_glyphs/dci/flattening.hpp"
#include "vicc_glyphs/design/design_builder.hpp"
#include "vicc_glyphs/pacemod/dashes.hpp"
#include "vicc_glyphs/pacemod/polygon_crossings.hpp"
#include "vicc_glyphs/render/renderer.hpp"

using namespace vicc_glyphs;
using namespace vicc_glyphs::design;
using vicc_glyphs::design::test::model;
using vicc_glyphs::design::test::shipped;

namespace {

// Shoelace area of a curve's control polygon (close enough to compare sizes).
double polygonSignedArea(const DiffusionCurve& curve) {
  double area = 0.0;
  const auto& p = curve.control_points;
  for (size_t i = 0; i + 1 < p.size(); ++i) {
    area += p[i].x() * p[i + 1].y() - p[i + 1].x() * p[i].y();
  }
  return 0.5 * area;
}

double polygonArea(const DiffusionCurve& curve) { return std::abs(polygonSignedArea(curve)); }

bool enclosedSideIsLeftForTest(const DiffusionCurve& curve) {
  return polygonSignedArea(curve) < 0.0;  // positive = clockwise on screen: inside on the right
}

bool sameGeometry(const DiffusionCurve& a, const DiffusionCurve& b) {
  if (a.control_points.size() != b.control_points.size()) return false;
  for (size_t i = 0; i < a.control_points.size(); ++i) {
    if ((a.control_points[i] - b.control_points[i]).norm() > 1e-9) return false;
  }
  return true;
}

}  // namespace

TEST(DesignBuild, RainSineWavesTheDropsOnlyAndMoreForLowerProbability) {
  const GlyphDesign design = shipped("rain_forecast_sine");
  const DiffusionCurveImage icon = loadIcon(design, 256);
  ASSERT_EQ(icon.curves.size(), 4u);
  const DiffusionCurveImage certain =
      buildGlyph(design, design.levelsFor({{"probability", 95}, {"amount", 5}}), model());
  const DiffusionCurveImage uncertain =
      buildGlyph(design, design.levelsFor({{"probability", 10}, {"amount", 5}}), model());
  ASSERT_EQ(certain.curves.size(), 4u);
  EXPECT_TRUE(sameGeometry(certain.curves[0], icon.curves[0]));  // the cloud is untouched
  for (int drop = 1; drop <= 3; ++drop) {
    EXPECT_FALSE(sameGeometry(certain.curves[drop], icon.curves[drop])) << drop;
    // More waves need more knot points.
    EXPECT_GT(uncertain.curves[drop].control_points.size(),
              certain.curves[drop].control_points.size())
        << drop;
  }
  EXPECT_EQ(validate(uncertain), "");
}

TEST(DesignBuild, RainAmountColoursAndSizesTheDrops) {
  const GlyphDesign design = shipped("rain_forecast_sine");
  const DiffusionCurveImage light =
      buildGlyph(design, design.levelsFor({{"probability", 95}, {"amount", 1}}), model());
  const DiffusionCurveImage heavy =
      buildGlyph(design, design.levelsFor({{"probability", 95}, {"amount", 20}}), model());
  EXPECT_GT(polygonArea(heavy.curves[2]), 1.2 * polygonArea(light.curves[2]));
  // Inner colour of a drop: the fill colour of its level (9ecae1 light, 08306b heavy).
  const auto has = [](const DiffusionCurve& c, const Color& rgb) {
    for (const auto* side : {&c.left_colors, &c.right_colors}) {
      for (const ColorPoint& p : *side) {
        if ((p.rgb - rgb).norm() < 1e-3) return true;
      }
    }
    return false;
  };
  EXPECT_TRUE(has(light.curves[1], Color(0x9e, 0xca, 0xe1) / 255.0));
  EXPECT_TRUE(has(heavy.curves[1], Color(0x08, 0x30, 0x6b) / 255.0));
}

TEST(DesignBuild, RainDashesHideDropsAndDashTheRest) {
  const GlyphDesign design = shipped("rain_forecast_dashes");
  const DiffusionCurveImage light =
      buildGlyph(design, design.levelsFor({{"probability", 50}, {"amount", 1}}), model());
  const DiffusionCurveImage heavy =
      buildGlyph(design, design.levelsFor({{"probability", 50}, {"amount", 20}}), model());
  // Light: cloud + 1 drop (+ its barrier); heavy: cloud + 3 drops + 3 barriers.
  EXPECT_EQ(light.curves.size(), 3u);
  EXPECT_EQ(heavy.curves.size(), 7u);
}

// Table 6.7's five probability classes on the heavy-rain glyph (3 drops): the four uncertain
// classes carry the four colour-frequency levels (dash count = round(arc length / the level's
// colour period), at least one more than the level below: on the short drops levels 2 and 3
// round to the same count), >= 90 % a solid contour; the dashes have the value V of
// colour-amplitude level 3.
TEST(DesignBuild, RainDashesShowAllFiveProbabilityClassesApart) {
  using perception::VisualVariable;
  const GlyphDesign design = shipped("rain_forecast_dashes");
  const DiffusionCurveImage plain = loadIcon(design, 0);
  const double value =
      model()
          .stimulus(VisualVariable::ColourAmplitude, 3, 50.0, perception::Waveform::Sine)
          .stimulus;
  const Color base = Color(0xa9, 0xc8, 0xee) / 255.0;
  const Color dash = base * (value / base.maxCoeff());
  EXPECT_NEAR(dash.maxCoeff(), 0.787, 0.001);  // level 3 of 4 in Table 6.1's 0.425-0.85
  const int model_levels[] = {3, 2, 1, 0, -1};
  int previous = 1 << 30;
  int k = 0;
  std::map<int, std::vector<int>> per_drop;
  for (double probability : {50.0, 65.0, 75.0, 85.0, 95.0}) {
    const DiffusionCurveImage glyph = buildGlyph(
        design, design.levelsFor({{"probability", probability}, {"amount", 20}}), model());
    int dashes = 0;
    for (int drop : {1, 2, 3}) {
      int dash_points = 0;
      for (const auto* side : {&glyph.curves[drop].left_colors, &glyph.curves[drop].right_colors}) {
        for (const ColorPoint& p : *side) dash_points += (p.rgb - dash).norm() < 1e-6;
      }
      // Expected: rounded counts, raised level by level to stay distinct.
      const double length_mm =
          pacemod::ChainArcLength(plain.curves[drop]).totalLength() / (plain.width / 50.0);
      int expected = 0;
      for (int level = 0; level <= model_levels[k]; ++level) {
        const double period_mm =
            model()
                .stimulus(VisualVariable::ColourFrequency, level, 50.0, perception::Waveform::Sine)
                .stimulus;
        expected =
            std::max({1, static_cast<int>(std::lround(length_mm / period_mm)), expected + 1});
      }
      EXPECT_EQ(dash_points, 2 * expected) << "probability " << probability << ", drop " << drop;
      EXPECT_TRUE(dash_points > 0 || model_levels[k] < 0);
      per_drop[drop].push_back(dash_points / 2);
      dashes += dash_points / 2;
    }
    EXPECT_LT(dashes, previous) << "probability " << probability;  // fewer dashes, more certain
    previous = dashes;
    ++k;
  }
  EXPECT_EQ(previous, 0);                        // >= 90 %: solid drop contours
  for (const auto& [drop, counts] : per_drop) {  // apart on every single drop, too
    for (size_t i = 1; i < counts.size(); ++i) EXPECT_LT(counts[i], counts[i - 1]) << drop;
  }
}

TEST(DesignBuild, IntracranialPressureInflatesTheBrainNotTheHead) {
  const GlyphDesign design = shipped("intracranial_pressure");
  const DiffusionCurveImage normal =
      buildGlyph(design, design.levelsFor({{"pressure", 10}, {"category", 0}}), model());
  const DiffusionCurveImage high =
      buildGlyph(design, design.levelsFor({{"pressure", 35}, {"category", 2}}), model());
  EXPECT_TRUE(sameGeometry(normal.curves[0], high.curves[0]));
  EXPECT_GT(polygonArea(high.curves[1]), 1.1 * polygonArea(normal.curves[1]));
}

TEST(DesignBuild, RendersAtTheRequestedSize) {
  const GlyphDesign design = shipped("rain_forecast_sine");
  const DiffusionCurveImage image = buildGlyph(design, {2, 1}, model(), 128);
  const RenderResult result = renderDiffusionCurves(image);
  EXPECT_EQ(result.image.cols, 128);
  EXPECT_THROW(buildGlyph(design, {5, 1}, model()), DesignValueError);
  EXPECT_THROW(buildGlyph(design, {1}, model()), DesignValueError);
}

// The glyph server and the map import a design's icon once and build every glyph on it.
TEST(DesignBuild, AnIconImportedOnceBuildsTheSameGlyphs) {
  for (const std::string name : {"rain_forecast_sine", "intracranial_pressure", "covid19_gradient",
                                 "rain_forecast_dashes"}) {
    const GlyphDesign design = shipped(name);
    const DiffusionCurveImage icon = loadIcon(design, 192);
    std::vector<int> levels(design.variables.size());
    for (size_t v = 0; v < levels.size(); ++v) levels[v] = design.variables[v].levelCount() - 1;
    const DiffusionCurveImage loaded = buildGlyph(design, levels, model(), 192);
    const DiffusionCurveImage reused = buildGlyph(design, levels, model(), icon);
    ASSERT_EQ(loaded.curves.size(), reused.curves.size()) << name;
    for (size_t c = 0; c < loaded.curves.size(); ++c) {
      EXPECT_TRUE(sameGeometry(loaded.curves[c], reused.curves[c])) << name << " curve " << c;
      EXPECT_EQ(loaded.curves[c].left_colors.size(), reused.curves[c].left_colors.size());
    }
    EXPECT_THROW(buildGlyph(design, std::vector<int>(levels.size(), -1), model(), icon),
                 DesignValueError);
  }
}

// A level out of range is the error, not the import (which it would otherwise wait for).
TEST(DesignBuild, ALevelOutOfRangeFailsBeforeTheIconIsRead) {
  GlyphDesign design = shipped("rain_forecast_sine");
  design.icon_path = "/nonexistent/icon.svg";
  EXPECT_THROW(buildGlyph(design, {9, 0}, model()), DesignValueError);
  EXPECT_ANY_THROW(buildGlyph(design, {0, 0}, model()));
}

TEST(DesignBuild, Covid19GradientGlyphAddsBandAndDashedCentre) {
  const GlyphDesign design = shipped("covid19_gradient");
  const DiffusionCurveImage icon = loadIcon(design, 192);
  ASSERT_EQ(icon.curves.size(), 1u);
  const auto build = [&](double incidence, double change, double hosp_change) {
    return buildGlyph(design,
                      design.levelsFor({{"incidence", incidence},
                                        {"hospitalisation", 3},
                                        {"incidence_change", change},
                                        {"hospitalisation_change", hosp_change}}),
                      model(), 192);
  };
  // Steady: no band, no dashes; only the centre region curve is added, and the contour is the
  // icon's scaled about the centre (the largest size, 0.95, leaves room for the waves).
  const DiffusionCurveImage steady = build(2000, 0, 0);
  EXPECT_EQ(steady.curves.size(), 2u);
  DiffusionCurve largest = icon.curves[0];
  for (Point2& p : largest.control_points) p = Point2(96, 96) + 0.95 * (p - Point2(96, 96));
  EXPECT_TRUE(sameGeometry(steady.curves[0], largest));
  // Rising: waved contour + band curve + centre curve + its dash barrier.
  const DiffusionCurveImage rising = build(400, 15, 30);
  EXPECT_EQ(rising.curves.size(), 4u);
  EXPECT_FALSE(sameGeometry(rising.curves[0], icon.curves[0]));
  EXPECT_EQ(validate(rising), "");
  // Size follows the incidence (Table 6.8): glyph scale 0.57 vs 0.95.
  const DiffusionCurveImage small = build(10, 0, 0), large = build(2000, 0, 0);
  EXPECT_NEAR(polygonArea(small.curves[0]) / polygonArea(large.curves[0]), 0.36, 0.01);
}

// A level whose modification reaches beyond the glyph would be clipped by the renderer (the
// COVID-19 glyph's largest size with its largest waves did): building it is an error naming the
// levels and the curve.
TEST(DesignBuild, AGlyphCarriedOutOfItsFrameIsAnError) {
  GlyphDesign design = shipped("covid19_gradient");
  const std::vector<int> largest = design.levelsFor({{"incidence", 2000},
                                                     {"hospitalisation", 3},
                                                     {"incidence_change", 15},
                                                     {"hospitalisation_change", 0}});
  EXPECT_NO_THROW(buildGlyph(design, largest, model(), 192));
  for (Encoding& encoding : design.variables[0].encodings) {
    if (encoding.channel == Channel::GlyphScale) encoding.numbers.back() = 1.0;  // as it was
  }
  try {
    buildGlyph(design, largest, model(), 192);
    ADD_FAILURE() << "no error for a glyph carried out of its frame";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("levels 5,2,4,2 carries curve 0 out of the 192 x 192 px"),
              std::string::npos)
        << e.what();
  }
}

TEST(DesignBuild, BandIsDarkerForARiseAndBrighterForAFall) {
  const GlyphDesign design = shipped("covid19_gradient");
  const auto bandColor = [&](double change) {
    const DiffusionCurveImage image = buildGlyph(design,
                                                 design.levelsFor({{"incidence", 400},
                                                                   {"hospitalisation", 3},
                                                                   {"incidence_change", change},
                                                                   {"hospitalisation_change", 0}}),
                                                 model(), 192);
    const DiffusionCurve& contour = image.curves[0];
    const auto& inside =
        enclosedSideIsLeftForTest(contour) ? contour.left_colors : contour.right_colors;
    return inside.front().rgb;
  };
  const Color fill = Color(0x14, 0x81, 0xd6) / 255.0;  // hospitalisation 3 -> ]2, 3] level
  EXPECT_LT(bandColor(15).maxCoeff(), 0.95 * fill.maxCoeff());
  EXPECT_GT(bandColor(-15).maxCoeff(), 1.05 * fill.maxCoeff());
}

// A band or a dashed centre inside a contour that gives its inside no colour would be drawn in
// black (a colour no level has): an error naming the curve instead.
TEST(DesignBuild, ABandOrCentreInsideAContourWithoutAnInsideColourIsAnError) {
  DiffusionCurveImage image;
  image.width = image.height = 100;
  DiffusionCurve square;
  square.control_points = vicc_glyphs::test::closedStraightChain(
      {Point2(20, 20), Point2(80, 20), Point2(80, 80), Point2(20, 80)});
  const double end = square.segmentCount();
  const bool left_inside = enclosedSideIsLeft(square);
  std::vector<ColorPoint>& outside = left_inside ? square.right_colors : square.left_colors;
  const Color white = Color::Ones();
  outside.push_back(ColorPoint{0.0, white});
  outside.push_back(ColorPoint{end, white});
  image.curves.push_back(square);
  ContourInsets insets(50.0);
  try {
    addContourBand(image, 0, insets, 2.0, 0.8, 1.2);
    ADD_FAILURE() << "no error for a band inside a contour without an inside colour";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("curve 0"), std::string::npos) << e.what();
  }
  EXPECT_THROW(addDashedCentre(image, 0, insets, 5.0, 4, Color(1, 0, 0), 50.0),
               std::invalid_argument);
  EXPECT_EQ(image.curves.size(), 1u);
}

// A level whose modification no selected curve can take would look like another level (here
// drops shrunk to nothing would keep their size): building that glyph is an error.
TEST(DesignBuild, AModificationNoCurveCanTakeIsAnError) {
  GlyphDesign design = shipped("rain_forecast_sine");
  for (DesignVariable& variable : design.variables) {
    for (Encoding& encoding : variable.encodings) {
      if (encoding.channel == Channel::Inflate) encoding.numbers.front() = -12.0;
    }
  }
  const std::vector<int> light = design.levelsFor({{"probability", 95}, {"amount", 1}});
  try {
    buildGlyph(design, light, model());
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("the inflation cannot be drawn"), std::string::npos)
        << e.what();
  }
  EXPECT_NO_THROW(
      buildGlyph(design, design.levelsFor({{"probability", 95}, {"amount", 5}}), model()));
}

// A fill colour to replace that the selected curves do not have left every level alike (the
// ICP brain with its colour one digit off rendered pink for all three categories).
TEST(DesignBuild, AFillColourThatIsNotOnTheCurvesIsAnError) {
  GlyphDesign design = shipped("intracranial_pressure");
  for (DesignVariable& variable : design.variables) {
    for (Encoding& encoding : variable.encodings) {
      if (encoding.channel == Channel::FillColor)
        encoding.replace = Color(0xe7, 0xa3, 0xae) / 255.0;
    }
  }
  try {
    buildGlyph(design, design.levelsFor({{"pressure", 10}, {"category", 0}}), model());
    ADD_FAILURE() << "no error";
  } catch (const DesignError& e) {
    EXPECT_NE(std::string(e.what()).find("the colour to replace, e7a3ae, is not on the selected"),
              std::string::npos)
        << e.what();
  }
}

// Shrunk drops leave the cloud: the gap and the sky around them are background, not a haze of
// the colours the drops and the cloud recorded where they touched.
// The darkest channel of the glyph for `amount` (mm/h) over a box given as fractions of the
// image.
float darkestIn(const std::string& design_name, double amount, double x0, double x1, double y0,
                double y1) {
  const GlyphDesign design = shipped(design_name);
  const DiffusionCurveImage glyph =
      buildGlyph(design, design.levelsFor({{"probability", 95}, {"amount", amount}}), model(), 256);
  const RenderResult result = renderDiffusionCurves(glyph);
  const cv::Mat& image = result.image;  // CV_32FC3, RGB in [0, 1]
  float lowest = 1.0f;
  for (int y = static_cast<int>(y0 * image.rows); y < static_cast<int>(y1 * image.rows); ++y) {
    for (int x = static_cast<int>(x0 * image.cols); x < static_cast<int>(x1 * image.cols); ++x) {
      const cv::Vec3f& rgb = image.at<cv::Vec3f>(y, x);
      lowest = std::min({lowest, rgb[0], rgb[1], rgb[2]});
    }
  }
  return lowest;
}

// Inflated drops: each side of a re-fitted contour takes the colour that covered most of it.
// The mean of its colour points (the drops recorded the cloud's grey where they touch it)
// made the outside of the heavy-rain drops grey and the sky below a haze down to the image's
// corners (173, 182, 191 there).
TEST(DesignBuild, InflatedDropsLeaveNoHaze) {
  EXPECT_GT(darkestIn("rain_forecast_sine", 20, 0.0, 0.1, 0.9, 1.0), 0.97f) << "bottom left";
  EXPECT_GT(darkestIn("rain_forecast_sine", 20, 0.02, 0.15, 0.72, 0.85), 0.97f) << "left of drops";
  EXPECT_GT(darkestIn("rain_forecast_sine", 20, 0.9, 1.0, 0.9, 1.0), 0.97f) << "bottom right";
}

TEST(DesignBuild, ShrunkDropsLeaveNoHaze) {
  EXPECT_GT(darkestIn("rain_forecast_sine", 1, 0.02, 0.15, 0.72, 0.85), 0.97f) << "left of drops";
  EXPECT_GT(darkestIn("rain_forecast_sine", 1, 0.38, 0.42, 0.72, 0.76), 0.97f) << "between drops";
}

// The cloud's underside above the outer drops stays cloud grey at every amount. The drops' tips
// used to reach into the cloud: the cloud kept a notch there, white under shrunk drops, a spike
// of the drops' colour above inflated ones.
TEST(DesignBuild, TheCloudsUndersideKeepsItsColourAboveTheDrops) {
  const cv::Vec3f cloud(0x6b / 255.0f, 0x7b / 255.0f, 0x8c / 255.0f);  // rain_cloud.svg's fill
  for (const std::string name : {"rain_forecast_sine", "rain_forecast_dashes"}) {
    const GlyphDesign design = shipped(name);
    const DiffusionCurveImage icon = loadIcon(design, 256);
    ASSERT_EQ(icon.curves.size(), 4u) << name;
    double bottom = 0.0;  // of the cloud (curve 0), px
    for (const Point2& p : icon.curves[0].control_points) bottom = std::max(bottom, p.y());
    std::vector<double> tips_x;  // the outer drops' (curves 1 and 3) uppermost points
    for (const int drop : {1, 3}) {
      const auto& points = icon.curves[drop].control_points;
      tips_x.push_back(std::min_element(points.begin(), points.end(), [](auto& a, auto& b) {
                         return a.y() < b.y();
                       })->x());
    }
    for (const double amount : {1.0, 5.0, 20.0}) {
      const RenderResult result = renderDiffusionCurves(buildGlyph(
          design, design.levelsFor({{"probability", 95}, {"amount", amount}}), model(), icon));
      float worst = 0.0f;
      for (const double x : tips_x) {
        for (int row = static_cast<int>(bottom) - 4; row <= static_cast<int>(bottom) - 2; ++row) {
          for (int col = static_cast<int>(x) - 8; col <= static_cast<int>(x) + 8; ++col) {
            const cv::Vec3f difference = result.image.at<cv::Vec3f>(row, col) - cloud;
            worst = std::max(
                {worst, std::abs(difference[0]), std::abs(difference[1]), std::abs(difference[2])});
          }
        }
      }
      EXPECT_LT(worst, 0.02f) << name << ", amount " << amount;
    }
  }
}

// Where a glyph's curves cross themselves as the renderer draws them, it puts their two sides
// the wrong way round: a smudge of one side's colour in the other. The COVID-19 glyph with its
// largest triangle waves had such crossings (found over all 900 level combinations at 96, 192
// and 512 px): thin folds of the waved outline at its concave corners that the polygon check's
// 16 points per segment did not resolve (teal smudges in the white around the glyph), and the
// band's inset edge looping over a crack of the inset region and over its cusps.
TEST(DesignBuild, CovidGlyphsDoNotCrossThemselvesAsDrawn) {
  const GlyphDesign design = shipped("covid19_gradient");
  struct Case {
    double incidence, hospitalisation, incidence_change, hospitalisation_change;
    int size;
  };
  // Each crossed before (outline folds at 512 px; the band's edge at 512 and at 96 px).
  for (const Case& c : {Case{400, 3.5, 15, 30, 512}, Case{700, 6, 15, 30, 512},
                        Case{75, 6, 15, 30, 512}, Case{400, 2.5, -5, -30, 96}}) {
    const DiffusionCurveImage glyph =
        buildGlyph(design,
                   design.levelsFor({{"incidence", c.incidence},
                                     {"hospitalisation", c.hospitalisation},
                                     {"incidence_change", c.incidence_change},
                                     {"hospitalisation_change", c.hospitalisation_change}}),
                   model(), c.size);
    std::vector<pacemod::Polyline> lines;
    for (const DiffusionCurve& curve : glyph.curves) lines.push_back(flattenCurve(curve));
    for (const pacemod::Crossing& x : pacemod::findCrossings(lines)) {
      ADD_FAILURE() << "incidence " << c.incidence << ", its change " << c.incidence_change << ", "
                    << c.size << " px: curve " << x.a.line << " crosses curve " << x.b.line
                    << " at (" << pacemod::crossingPoint(lines, x).transpose() << ")";
    }
  }
}

// Hiding drops must not take the colour of the drop that stays (same colour, other curve).
TEST(DesignBuild, HiddenDropsLeaveTheRemainingDropFilled) {
  const GlyphDesign design = shipped("rain_forecast_dashes");
  const DiffusionCurveImage one =
      buildGlyph(design, design.levelsFor({{"probability", 95}, {"amount", 1}}), model(), 256);
  ASSERT_EQ(one.curves.size(), 2u);  // the cloud and one drop
  const DiffusionCurve& drop = one.curves[1];
  const auto& inside = enclosedSideIsLeftForTest(drop) ? drop.left_colors : drop.right_colors;
  ASSERT_FALSE(inside.empty());
  for (const ColorPoint& point : inside) {
    EXPECT_LT(point.rgb.minCoeff(), 0.7) << "the drop's fill turned to the background";
  }
}
