// The visual encoding engine: Table 4.1 rows, the Fig. 4.6 patient before and after surgery,
// alternation and the category filter, proxies, overlays.
#include <gtest/gtest.h>

#include <cmath>

#include "test_support.hpp"
#include "vicc_anatomy_viz/encoded_status_json.hpp"
#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/status_encoder.hpp"

namespace vicc_anatomy_viz {
namespace {

using test::figurePatient;
using test::finding;
using test::shippedModel;

const std::string kView = "neurological_status_sdh";

EncodedStatus encode(const Examination& examination, std::vector<std::string> hidden = {}) {
  const StatusEncoder encoder(shippedModel(), kView);
  EncodeOptions options;
  options.hidden_categories = std::move(hidden);
  return encoder.encode(examination.patient_id, examination, options);
}

Examination examinationOf(std::vector<Finding> findings) {
  Examination examination;
  examination.patient_id = "TEST-1";
  examination.taken_at_us = 1700000000 * kMicrosPerSecond;
  examination.findings = std::move(findings);
  return examination;
}

const EncodedStructure* entry(const EncodedStatus& status, const std::string& category,
                              const std::string& structure, Side side) {
  for (const auto& e : status.structures) {
    if (e.category == category && e.structure_id == structure && e.side == side) return &e;
  }
  return nullptr;
}

// Each row of Table 4.1 (final categories): hue of the category and level count of each
// property's visual variable, encoded from a finding at the strongest abnormal value.
TEST(StatusEncoderTest, EachTable41RowEncodesToItsHueAndLevelCount) {
  struct Row {
    Finding finding;
    std::string hue;
    double hue_deg;
    int intensity_levels;
    std::string texture;
    int texture_levels;
    bool proxy;
  };
  const std::vector<Row> rows = {
      {finding("radicular_pain", "dermatome_L4", Side::kLeft,
               {{"intensity", Value::number(10)}, {"trigger", Value::label("stress")}}),
       "red", 0.0, 3, "normal_perturbation", 1, false},
      {finding("paresis", "quadriceps_femoris", Side::kLeft,
               {{"muscle_strength", Value::number(1)}}),
       "purple", 280.0, 3, "", 0, false},
      {finding("t_reflex", "patellar_ligament", Side::kRight, {{"intensity", Value::number(5)}}),
       "green", 125.0, 5, "", 0, true},
      {finding("excretion_disorder", "urethra", Side::kNone, {{"intensity", Value::label("true")}}),
       "orange", 30.0, 1, "", 0, true},
      {finding("sensory_disorder", "dermatome_S1", Side::kRight,
               {{"intensity", Value::number(4)}, {"paresthesia", Value::number(3)}}),
       "cyan", 185.0, 4, "noise", 3, false},
  };
  const View& view = shippedModel().view(kView);
  for (const auto& row : rows) {
    const EncodedStatus status = encode(examinationOf({row.finding}));
    ASSERT_EQ(status.structures.size(), 1u) << row.finding.category;
    const EncodedStructure& e = status.structures[0];
    EXPECT_EQ(view.hueOf(row.finding.category), row.hue);
    EXPECT_DOUBLE_EQ(e.hue_deg, row.hue_deg) << row.finding.category;
    EXPECT_EQ(e.intensity_levels, row.intensity_levels) << row.finding.category;
    EXPECT_EQ(e.intensity_level, row.intensity_levels) << "strongest value, strongest level";
    EXPECT_DOUBLE_EQ(e.saturation, 1.0);
    EXPECT_DOUBLE_EQ(e.brightness, 0.6);
    EXPECT_EQ(e.texture_id, row.texture) << row.finding.category;
    EXPECT_EQ(e.texture_levels, row.texture_levels) << row.finding.category;
    EXPECT_EQ(e.texture_level, row.texture_levels) << row.finding.category;
    EXPECT_EQ(e.proxy, row.proxy) << row.finding.category;
    EXPECT_FLOAT_EQ(e.color.a, 1.0f);
  }
}

TEST(StatusEncoderTest, ColoursFollowHueAndSaturationBrightness) {
  const EncodedStatus status = encode(examinationOf(
      {finding("radicular_pain", "dermatome_L4", Side::kLeft, {{"intensity", Value::number(8)}}),
       finding("radicular_pain", "dermatome_L3", Side::kLeft, {{"intensity", Value::number(5)}}),
       finding("radicular_pain", "dermatome_L2", Side::kLeft, {{"intensity", Value::number(2)}})}));
  ASSERT_EQ(status.structures.size(), 3u);
  // Catalogue order L2, L3, L4: levels 1, 2, 3 of 3, spread over the 5-value range.
  const EncodedStructure& weak = status.structures[0];
  const EncodedStructure& middle = status.structures[1];
  const EncodedStructure& strong = status.structures[2];
  EXPECT_EQ(weak.intensity_level, 1);
  EXPECT_DOUBLE_EQ(weak.saturation, 0.3);
  EXPECT_DOUBLE_EQ(weak.brightness, 1.0);
  EXPECT_EQ(middle.intensity_level, 2);
  EXPECT_DOUBLE_EQ(middle.saturation, 0.65);
  EXPECT_DOUBLE_EQ(middle.brightness, 0.8);
  EXPECT_EQ(strong.intensity_level, 3);
  // Red at saturation 1, brightness 0.6.
  EXPECT_FLOAT_EQ(strong.color.r, 0.6f);
  EXPECT_FLOAT_EQ(strong.color.g, 0.0f);
  EXPECT_FLOAT_EQ(strong.color.b, 0.0f);
  // Red at saturation 0.3, brightness 1: (1, 0.7, 0.7).
  EXPECT_FLOAT_EQ(weak.color.r, 1.0f);
  EXPECT_NEAR(weak.color.g, 0.7f, 1e-6);
  EXPECT_NEAR(weak.color.b, 0.7f, 1e-6);
}

// Fig. 4.6 (A)-(B): severe pain and hypoesthesia alternating on the left L5 dermatome, moderate
// paresis of the right extensor hallucis longus, mild paresis of the right tibialis anterior,
// asymmetric patellar reflex shown by proxies.
TEST(StatusEncoderTest, Figure46PreOperativeStatus) {
  const EncodedStatus status = encode(figurePatient()[0]);
  ASSERT_TRUE(status.has_examination);
  EXPECT_EQ(status.structures.size(), 7u);  // and the (illustrative) ICP of 26 mmHg

  const EncodedStructure* pain = entry(status, "radicular_pain", "dermatome_L5", Side::kLeft);
  const EncodedStructure* hypo = entry(status, "sensory_disorder", "dermatome_L5", Side::kLeft);
  ASSERT_TRUE(pain && hypo);
  EXPECT_DOUBLE_EQ(pain->hue_deg, 0.0);
  EXPECT_EQ(pain->intensity_level, 3);  // severe: 8 of 10 -> level 3 of 3
  EXPECT_EQ(pain->texture_id, "");      // constant pain is the normal trigger
  EXPECT_DOUBLE_EQ(hypo->hue_deg, 185.0);
  EXPECT_EQ(hypo->intensity_level, 2);
  EXPECT_EQ(hypo->intensity_levels, 4);
  ASSERT_EQ(status.alternations.size(), 1u);
  const Alternation& alternation = status.alternations[0];
  EXPECT_EQ(alternation.structure_id, "dermatome_L5");
  EXPECT_EQ(alternation.side, Side::kLeft);
  EXPECT_EQ(alternation.categories,
            (std::vector<std::string>{"radicular_pain", "sensory_disorder"}));
  EXPECT_EQ(pain->alternation_group, 0);
  EXPECT_EQ(hypo->alternation_group, 0);

  const EncodedStructure* ehl = entry(status, "paresis", "extensor_hallucis_longus", Side::kRight);
  const EncodedStructure* ta = entry(status, "paresis", "tibialis_anterior", Side::kRight);
  ASSERT_TRUE(ehl && ta);
  EXPECT_DOUBLE_EQ(ehl->hue_deg, 280.0);
  EXPECT_EQ(ehl->intensity_level, 2);  // moderate
  EXPECT_EQ(ta->intensity_level, 1);   // mild
  EXPECT_EQ(ehl->fma_id, "FMA:22533");
  EXPECT_FALSE(ehl->proxy);
  EXPECT_EQ(ehl->alternation_group, -1);
  ASSERT_EQ(ehl->properties.size(), 1u);
  EXPECT_EQ(ehl->properties[0].value, "3");
  EXPECT_EQ(ehl->properties[0].derived_value, "moderate");
  EXPECT_NE(ehl->overlay_text.find("M. extensor hallucis longus (right)"), std::string::npos);
  EXPECT_NE(ehl->overlay_text.find("muscle strength (MRC) 3"), std::string::npos);

  const EncodedStructure* left = entry(status, "t_reflex", "patellar_ligament", Side::kLeft);
  const EncodedStructure* right = entry(status, "t_reflex", "patellar_ligament", Side::kRight);
  ASSERT_TRUE(left && right);  // both sides, since they differ
  EXPECT_TRUE(left->proxy);
  EXPECT_TRUE(right->proxy);
  EXPECT_EQ(left->intensity_level, 2);
  EXPECT_EQ(right->intensity_level, 3);
  EXPECT_TRUE(right->properties[0].normal);
  EXPECT_DOUBLE_EQ(left->hue_deg, 125.0);

  EXPECT_EQ(entry(status, "excretion_disorder", "urethra", Side::kNone), nullptr);  // normal
}

// Fig. 4.6 (C): symmetric patellar reflex, decreased hypoesthesia with paresthesia, remaining
// mild paresis of the right extensor hallucis longus.
TEST(StatusEncoderTest, Figure46PostOperativeChanges) {
  const EncodedStatus status = encode(figurePatient()[1]);
  EXPECT_EQ(status.structures.size(), 2u);
  EXPECT_TRUE(status.alternations.empty());
  EXPECT_EQ(entry(status, "radicular_pain", "dermatome_L5", Side::kLeft), nullptr);
  EXPECT_EQ(entry(status, "t_reflex", "patellar_ligament", Side::kLeft), nullptr);
  EXPECT_EQ(entry(status, "t_reflex", "patellar_ligament", Side::kRight), nullptr);
  EXPECT_EQ(entry(status, "paresis", "tibialis_anterior", Side::kRight), nullptr);

  const EncodedStructure* sensory = entry(status, "sensory_disorder", "dermatome_L5", Side::kLeft);
  ASSERT_NE(sensory, nullptr);
  EXPECT_EQ(sensory->intensity_level, 1);  // decreased from 2
  EXPECT_EQ(sensory->texture_id, "noise");
  EXPECT_EQ(sensory->texture_level, 2);
  EXPECT_EQ(sensory->texture_levels, 3);
  EXPECT_DOUBLE_EQ(sensory->texture_frequency, 8.0);
  EXPECT_DOUBLE_EQ(sensory->texture_amplitude, 0.65);
  EXPECT_EQ(sensory->alternation_group, -1);

  const EncodedStructure* ehl = entry(status, "paresis", "extensor_hallucis_longus", Side::kRight);
  ASSERT_NE(ehl, nullptr);
  EXPECT_EQ(ehl->intensity_level, 1);  // moderate -> mild
  EXPECT_EQ(ehl->properties[0].derived_value, "mild");
}

TEST(StatusEncoderTest, CategoryFilterResolvesTheAlternation) {
  const EncodedStatus status = encode(figurePatient()[0], {"radicular_pain"});
  EXPECT_TRUE(status.alternations.empty());
  EXPECT_EQ(entry(status, "radicular_pain", "dermatome_L5", Side::kLeft), nullptr);
  const EncodedStructure* hypo = entry(status, "sensory_disorder", "dermatome_L5", Side::kLeft);
  ASSERT_NE(hypo, nullptr);
  EXPECT_EQ(hypo->alternation_group, -1);
  ASSERT_EQ(status.legend.size(), 6u);
  EXPECT_EQ(status.legend[0].id, "radicular_pain");
  EXPECT_FALSE(status.legend[0].visible);
  EXPECT_EQ(status.legend[0].count, 1u);  // still counted, so the panel can say it is hidden
  EXPECT_TRUE(status.legend[4].visible);
  EXPECT_EQ(status.hidden_categories, std::vector<std::string>{"radicular_pain"});
}

TEST(StatusEncoderTest, UnknownFilterCategoryIsRejected) {
  try {
    encode(figurePatient()[0], {"fever"});
    FAIL();
  } catch (const ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("'fever' is not a category of view"), std::string::npos);
  }
}

TEST(StatusEncoderTest, NoExaminationGivesAnEmptyStatusWithLegend) {
  const StatusEncoder encoder(shippedModel(), kView);
  const EncodedStatus status = encoder.encode("SDH-046", std::nullopt, {"1999-01-01", {}});
  EXPECT_FALSE(status.has_examination);
  EXPECT_TRUE(status.structures.empty());
  EXPECT_EQ(status.legend.size(), 6u);
  EXPECT_EQ(status.requested_date, "1999-01-01");
  EXPECT_EQ(status.notes.size(), 3u);
}

TEST(StatusEncoderTest, ParesthesiaWithoutHypoesthesiaIsAPaleTintWithNoise) {
  const EncodedStatus status = encode(examinationOf({finding(
      "sensory_disorder", "dermatome_C6", Side::kRight, {{"paresthesia", Value::number(2)}})}));
  ASSERT_EQ(status.structures.size(), 1u);
  const EncodedStructure& e = status.structures[0];
  EXPECT_EQ(e.intensity_level, 0);
  EXPECT_DOUBLE_EQ(e.saturation, 0.12);
  EXPECT_EQ(e.texture_id, "noise");
  EXPECT_EQ(e.texture_level, 2);
}

TEST(StatusEncoderTest, SymmetricReflexesShowOnlyWhenAbnormal) {
  const auto both = [](int value) {
    return examinationOf({finding("t_reflex", "calcaneal_tendon", Side::kLeft,
                                  {{"intensity", Value::number(value)}}),
                          finding("t_reflex", "calcaneal_tendon", Side::kRight,
                                  {{"intensity", Value::number(value)}})});
  };
  EXPECT_TRUE(encode(both(3)).structures.empty());
  const EncodedStatus absent = encode(both(1));
  ASSERT_EQ(absent.structures.size(), 2u);
  EXPECT_EQ(absent.structures[0].side, Side::kLeft);
  EXPECT_EQ(absent.structures[0].intensity_level, 1);
}

TEST(StatusEncoderTest, StressTriggeredPainGetsTheNormalPerturbationTexture) {
  const EncodedStatus status = encode(examinationOf(
      {finding("radicular_pain", "dermatome_S1", Side::kRight,
               {{"intensity", Value::number(5)}, {"trigger", Value::label("stress")}})}));
  ASSERT_EQ(status.structures.size(), 1u);
  EXPECT_EQ(status.structures[0].texture_id, "normal_perturbation");
  EXPECT_DOUBLE_EQ(status.structures[0].texture_frequency, 6.0);
  EXPECT_NE(status.structures[0].overlay_text.find("intensity 5 [0..10], trigger stress"),
            std::string::npos);
}

TEST(StatusEncoderTest, TransparencyEncodesLevelsAsAlpha) {
  YAML::Node root = test::shippedConfigYaml();
  test::entryWithId(root["categories"], "t_reflex")["props"][0]["visual_variable"] = "transparency";
  const EncodingModel model = test::modelFrom(root);
  const StatusEncoder encoder(model, kView);
  const EncodedStatus status =
      encoder.encode("TEST-1", examinationOf({finding("t_reflex", "calcaneal_tendon", Side::kLeft,
                                                      {{"intensity", Value::number(1)}}),
                                              finding("t_reflex", "calcaneal_tendon", Side::kRight,
                                                      {{"intensity", Value::number(5)}})}));
  ASSERT_EQ(status.structures.size(), 2u);
  EXPECT_FLOAT_EQ(status.structures[0].color.a, 0.85f);          // level 1 of 3: weakest alpha
  EXPECT_FLOAT_EQ(status.structures[1].color.a, 0.35f);          // level 3 of 3: strongest
  EXPECT_EQ(status.structures[1].properties[0].level_count, 3);  // 5 values quantized to 3
  EXPECT_DOUBLE_EQ(status.structures[1].saturation, 1.0);        // no intensity variable left
}

TEST(StatusEncoderTest, RecordsThatNoLongerFitAreLeftOutWithANote) {
  Examination examination = examinationOf(
      {finding("paresis", "tibialis_posterior", Side::kLeft,
               {{"muscle_strength", Value::number(2)}}),
       finding("paresis", "gastrocnemius", Side::kLeft, {{"muscle_strength", Value::number(9)}}),
       finding("paresis", "gastrocnemius", Side::kRight, {{"muscle_strength", Value::number(2)}})});
  const EncodedStatus status = encode(examination);
  ASSERT_EQ(status.structures.size(), 1u);
  EXPECT_EQ(status.structures[0].side, Side::kRight);
  std::size_t skipped = 0;
  for (const auto& note : status.notes) skipped += note.rfind("not shown: ", 0) == 0;
  EXPECT_EQ(skipped, 2u);
  // What is left out is unknown, not normal: the status says it is partial.
  EXPECT_TRUE(status.partial);
  EXPECT_EQ(status.partial_reason,
            "2 recorded finding(s) not shown: they no longer fit the configuration");
  EXPECT_NE(status.structures[0].overlay_text.find("[partial examination]"), std::string::npos);
  // Findings of categories outside the view belong to another usage, not to a gap.
  const EncodedStatus motor =
      StatusEncoder(shippedModel(), "motor_status")
          .encode("TEST-1", examinationOf({finding("sensory_disorder", "dermatome_L5", Side::kLeft,
                                                   {{"intensity", Value::number(1)}})}));
  EXPECT_FALSE(motor.partial);
}

TEST(StatusEncoderTest, JsonCarriesEverythingTheAvatarNeeds) {
  const nlohmann::json json = toJson(encode(figurePatient()[0]));
  EXPECT_EQ(json["format"], "vicc-encoded-status");
  EXPECT_EQ(json["patient_id"], "SDH-046");
  EXPECT_EQ(json["examination_time"], "2023-03-06T09:15:00Z");
  ASSERT_EQ(json["structures"].size(), 7u);  // with the (illustrative) ICP of 26 mmHg
  const auto& first = json["structures"][0];
  for (const char* key : {"structure_id", "side", "category", "rgba", "hsv", "intensity_level",
                          "intensity_levels", "texture", "proxy", "overlay_text", "properties",
                          "alternation_group", "fma_id", "display_name"}) {
    EXPECT_TRUE(first.contains(key)) << key;
  }
  EXPECT_EQ(first["rgba"].size(), 4u);
  EXPECT_EQ(json["alternations"][0]["categories"],
            nlohmann::json({"radicular_pain", "sensory_disorder"}));
  EXPECT_EQ(json["legend"].size(), 6u);
  EXPECT_EQ(json["notes"].size(), 3u);  // two quantizations (pain, ICP), one spatial conflict
}

TEST(StatusEncoderTest, PartialAndPreliminaryExaminationsSaySoEverywhere) {
  Examination examination = examinationOf({test::finding(
      "radicular_pain", "dermatome_L5", Side::kLeft, {{"intensity", Value::number(6)}})});
  EncodedStatus complete = encode(examination);
  EXPECT_FALSE(complete.partial);
  EXPECT_EQ(complete.structures.at(0).overlay_text.find("partial"), std::string::npos);

  examination.partial = true;
  examination.partial_reason = "1 observation(s) not imported";
  examination.status = ExaminationStatus::kPreliminary;
  const EncodedStatus status = encode(examination);
  EXPECT_TRUE(status.partial);
  EXPECT_EQ(status.partial_reason, examination.partial_reason);
  EXPECT_EQ(status.examination_status, ExaminationStatus::kPreliminary);
  const std::string& overlay = status.structures.at(0).overlay_text;
  EXPECT_NE(overlay.find("[partial examination]"), std::string::npos) << overlay;
  EXPECT_NE(overlay.find("[preliminary]"), std::string::npos) << overlay;
  ASSERT_GE(status.notes.size(), 2u);
  EXPECT_NE(status.notes[0].find("PRELIMINARY"), std::string::npos);
  EXPECT_NE(status.notes[1].find("PARTIAL EXAMINATION (1 observation(s) not imported)"),
            std::string::npos);
  // A partial examination without findings is not "no abnormal findings": the flag travels.
  examination.findings.clear();
  const nlohmann::json document = toJson(encode(examination));
  EXPECT_TRUE(document["examination_partial"].get<bool>());
  EXPECT_EQ(document["examination_status"], "preliminary");
}

}  // namespace
}  // namespace vicc_anatomy_viz
