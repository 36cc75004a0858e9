#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "synthetic_avatar.hpp"
#include "vicc_anatomy_viz/avatar_view/draw_state.hpp"

namespace vicc_anatomy_viz::avatar_view {
namespace {

using testing::entry;
using testing::statusWith;
using testing::syntheticAvatar;

bool mentions(const std::vector<std::string>& warnings, const std::string& text) {
  for (const auto& warning : warnings)
    if (warning.find(text) != std::string::npos) return true;
  return false;
}

TEST(DrawStateTest, PlacesDermatomesOnSkinMusclesOnMeshesTendonsOnProxies) {
  const avatar::AvatarModel model = syntheticAvatar();
  EncodedStatus status = statusWith({entry("dermatome_L5", Side::kRight, "hypoesthesia"),
                                     entry("extensor_hallucis_longus", Side::kRight, "paresis"),
                                     entry("patellar_tendon", Side::kLeft, "reflex")});
  status.structures[2].proxy = true;
  const AvatarDrawState state = buildDrawState(status, model);
  ASSERT_EQ(state.items.size(), 3u);
  EXPECT_TRUE(state.warnings.empty());
  EXPECT_EQ(state.items[0].target, TargetKind::kSkinRegion);
  EXPECT_EQ(state.items[0].target_index, 1);  // the right L5 region, not the left one
  EXPECT_EQ(state.items[1].target, TargetKind::kStructureMesh);
  EXPECT_EQ(state.items[1].target_index, 0);
  EXPECT_EQ(state.items[2].target, TargetKind::kProxy);
  EXPECT_EQ(state.items[2].target_index, 1);  // left tendon
  EXPECT_FLOAT_EQ(state.items[1].color.r, 1.f);
}

TEST(DrawStateTest, UnknownStructureAndWrongSideAreWarnedAndTheRestDrawn) {
  const AvatarDrawState state =
      buildDrawState(statusWith({entry("spleen", Side::kNone, "pain"),
                                 entry("extensor_hallucis_longus", Side::kLeft, "paresis"),
                                 entry("dermatome_L5", Side::kLeft, "pain")}),
                     syntheticAvatar());
  ASSERT_EQ(state.items.size(), 1u);
  EXPECT_EQ(state.items[0].structure_id, "dermatome_L5");
  ASSERT_EQ(state.warnings.size(), 2u);
  EXPECT_TRUE(mentions(state.warnings, "spleen"));
  EXPECT_TRUE(mentions(state.warnings, "extensor_hallucis_longus (left)"));
}

TEST(DrawStateTest, NanOrOutOfRangeColourIsNotDrawn) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const AvatarDrawState state =
      buildDrawState(statusWith({entry("dermatome_L5", Side::kLeft, "pain", {nan, 0.f, 0.f, 1.f}),
                                 entry("dermatome_L5", Side::kRight, "pain", {1.5f, 0.f, 0.f, 1.f}),
                                 entry("extensor_hallucis_longus", Side::kRight, "paresis")}),
                     syntheticAvatar());
  ASSERT_EQ(state.items.size(), 1u);
  EXPECT_EQ(state.items[0].category, "paresis");
  EXPECT_EQ(state.warnings.size(), 2u);
  EXPECT_TRUE(mentions(state.warnings, "colour"));
}

TEST(DrawStateTest, EmptyStatusWarnsWithNoExamination) {
  EncodedStatus status;
  status.patient_id = "SDH-T";
  status.requested_date = "2020-01-01";
  const AvatarDrawState state = buildDrawState(status, syntheticAvatar());
  EXPECT_TRUE(state.items.empty());
  ASSERT_EQ(state.warnings.size(), 1u);
  EXPECT_EQ(state.warnings[0], "SDH-T: no examination at or before 2020-01-01");
}

TEST(DrawStateTest, HiddenCategoriesAreLeftOutAndMarkedInTheLegend) {
  EncodedStatus status = statusWith({entry("dermatome_L5", Side::kLeft, "pain"),
                                     entry("dermatome_L5", Side::kRight, "hypoesthesia")});
  LegendEntry pain{"pain", "Pain", "red", {1.f, 0.f, 0.f, 1.f}, false, 1};
  LegendEntry hypo{"hypoesthesia", "Hypoesthesia", "blue", {0.f, 0.f, 1.f, 1.f}, true, 1};
  status.legend = {pain, hypo};
  const AvatarDrawState state = buildDrawState(status, syntheticAvatar());
  ASSERT_EQ(state.items.size(), 1u);
  EXPECT_EQ(state.items[0].category, "hypoesthesia");
  ASSERT_EQ(state.legend.size(), 2u);
  EXPECT_EQ(state.legend[0].label, "Pain (red): 1 [hidden]");
  EXPECT_FALSE(state.legend[0].visible);
  EXPECT_EQ(state.legend[1].label, "Hypoesthesia (blue): 1");
}

TEST(DrawStateTest, TexturesAreReadAndBadOnesWarned) {
  EncodedStatus status = statusWith({entry("dermatome_L5", Side::kLeft, "pain"),
                                     entry("dermatome_L5", Side::kRight, "paresthesia"),
                                     entry("extensor_hallucis_longus", Side::kRight, "paresis")});
  status.structures[0].texture_id = "normal_perturbation";
  status.structures[0].texture_level = 1;
  status.structures[0].texture_levels = 1;
  status.structures[0].texture_frequency = 6.0;
  status.structures[0].texture_amplitude = 0.6;
  status.structures[1].texture_id = "noise";
  status.structures[1].texture_level = 2;
  status.structures[1].texture_levels = 3;
  status.structures[1].texture_frequency = std::numeric_limits<double>::quiet_NaN();
  status.structures[2].texture_id = "stripes";
  status.structures[2].texture_level = 1;
  const AvatarDrawState state = buildDrawState(status, syntheticAvatar());
  ASSERT_EQ(state.items.size(), 1u);
  EXPECT_EQ(state.items[0].texture.kind, TextureKind::kNormalPerturbation);
  EXPECT_FLOAT_EQ(state.items[0].texture.frequency, 6.f);
  EXPECT_FLOAT_EQ(state.items[0].texture.amplitude, 0.6f);
  EXPECT_TRUE(mentions(state.warnings, "invalid texture parameters"));
  EXPECT_TRUE(mentions(state.warnings, "unknown texture 'stripes'"));
}

TEST(DrawStateTest, AlternationGroupOutOfRangeIsWarnedAndDrawnAlone) {
  EncodedStatus status = statusWith({entry("dermatome_L5", Side::kLeft, "pain")});
  status.structures[0].alternation_group = 3;
  const AvatarDrawState state = buildDrawState(status, syntheticAvatar());
  ASSERT_EQ(state.items.size(), 1u);
  EXPECT_EQ(state.items[0].alternation_group, -1);
  EXPECT_TRUE(mentions(state.warnings, "alternation group 3"));
  // A group that exists but does not list the entry is not trusted either.
  status.alternations.resize(1);
  status.structures[0].alternation_group = 0;
  EXPECT_EQ(buildDrawState(status, syntheticAvatar()).items[0].alternation_group, -1);
}

TEST(DrawStateTest, HeadlineNamesPreliminaryAndPartialExaminations) {
  EncodedStatus status = statusWith({});
  status.examination_time = 0;
  status.examination_status = ExaminationStatus::kPreliminary;
  status.partial = true;
  status.partial_reason = "2 observations not imported";
  const AvatarDrawState state = buildDrawState(status, syntheticAvatar());
  EXPECT_NE(state.headline.find("PRELIMINARY"), std::string::npos);
  EXPECT_NE(state.headline.find("PARTIAL (2 observations not imported)"), std::string::npos);
}

}  // namespace
}  // namespace vicc_anatomy_viz::avatar_view
