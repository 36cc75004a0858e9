// The ICP category of the shipped configuration and what the status glyph reads from an
// examination: the recorded value and its level, "no data" whenever the value is missing.
#include <gtest/gtest.h>

#include "../core/test_support.hpp"
#include "vicc_anatomy_viz/examination_validator.hpp"
#include "vicc_anatomy_viz/status_glyph/glyph_reading.hpp"

namespace {

using namespace vicc_anatomy_viz;
using status_glyph::GlyphBinding;
using status_glyph::readGlyph;
using status_glyph::ReadingKind;
namespace t = vicc_anatomy_viz::test;

constexpr const char* kView = "neurological_status_sdh";

Examination withIcp(std::map<std::string, Value> values) {
  Examination examination = t::figurePatient()[0];
  examination.findings.erase(
      std::remove_if(examination.findings.begin(), examination.findings.end(),
                     [](const Finding& f) { return f.category == "intracranial_pressure"; }),
      examination.findings.end());
  examination.findings.push_back(
      t::finding("intracranial_pressure", "brain", Side::kNone, std::move(values)));
  return examination;
}

TEST(IcpConfigurationTest, IsANumericalMmHgPropertyWithNormalRangeAndTwoLevels) {
  const Category& icp = t::shippedModel().category("intracranial_pressure");
  ASSERT_TRUE(icp.refersTo("brain"));
  const Property* pressure = icp.property("intensity");
  ASSERT_NE(pressure, nullptr);
  EXPECT_EQ(pressure->domain.type, DataType::kNumerical);
  EXPECT_EQ(pressure->domain.min, 0);
  EXPECT_EQ(pressure->domain.max, 80);
  EXPECT_NE(pressure->label.find("mmHg"), std::string::npos);
  for (int v = 0; v <= 15; ++v) EXPECT_TRUE(pressure->isNormal(Value::number(v))) << v;
  EXPECT_FALSE(pressure->isNormal(Value::number(16)));
  const LevelMapping& levels = t::shippedModel().levels("intracranial_pressure", "intensity");
  EXPECT_EQ(levels.levelCount(), 2);
  EXPECT_EQ(levels.levelOf(Value::number(15)), 0);
  EXPECT_EQ(levels.levelOf(Value::number(16)), 1);
  EXPECT_EQ(levels.levelOf(Value::number(22)), 1);
  EXPECT_EQ(levels.levelOf(Value::number(23)), 2);
  EXPECT_EQ(levels.levelOf(Value::number(80)), 2);
  EXPECT_EQ(t::shippedModel().view(kView).hueOf("intracranial_pressure"), "blue");
}

TEST(IcpConfigurationTest, ValuesOutsideTheDomainAreRejectedNamingTheFinding) {
  const ExaminationValidator validator(t::shippedModel(), kView);
  for (const int outside : {-1, 81}) {
    const auto problems = validator.problems(withIcp({{"intensity", Value::number(outside)}}));
    ASSERT_FALSE(problems.empty()) << outside << " mmHg accepted";
    const std::string all = ::testing::PrintToString(problems);
    EXPECT_NE(all.find("intracranial_pressure"), std::string::npos) << all;
  }
  EXPECT_TRUE(validator.problems(withIcp({{"intensity", Value::number(80)}})).empty());
}

TEST(IcpConfigurationTest, AWrongNormalRangeIsRejectedNamingTheProperty) {
  YAML::Node root = t::shippedConfigYaml();
  YAML::Node icp = t::entryWithId(root["categories"], "intracranial_pressure");
  icp["props"][0]["normal"].push_back(81);
  const std::string message = t::rejection(root);
  EXPECT_NE(message.find("intracranial_pressure"), std::string::npos) << message;
  EXPECT_NE(message.find("81"), std::string::npos) << message;
}

TEST(IcpConfigurationTest, TheSamplePatientHasIllustrativeValuesAtBothDates) {
  const auto examinations = t::figurePatient();
  ASSERT_EQ(examinations.size(), 2u);
  const GlyphBinding binding;
  const auto before = readGlyph(t::shippedModel(), binding, examinations[0], false);
  const auto after = readGlyph(t::shippedModel(), binding, examinations[1], false);
  ASSERT_EQ(before.kind, ReadingKind::kValue);
  ASSERT_EQ(after.kind, ReadingKind::kValue);
  EXPECT_EQ(before.value, 26);
  EXPECT_EQ(before.level, 2);
  EXPECT_EQ(after.value, 12);
  EXPECT_EQ(after.level, 0);
  EXPECT_NE(after.caption.find("normal"), std::string::npos) << after.caption;
  EXPECT_NE(before.caption.find("level 2/2"), std::string::npos) << before.caption;
}

TEST(GlyphReadingTest, AMissingFindingIsNoDataNeverNormal) {
  Examination examination = withIcp({});
  examination.findings.pop_back();  // no ICP finding at all
  const auto reading = readGlyph(t::shippedModel(), GlyphBinding(), examination, false);
  EXPECT_EQ(reading.kind, ReadingKind::kNoData);
  EXPECT_NE(reading.caption.find("no data"), std::string::npos) << reading.caption;
  EXPECT_EQ(reading.caption.find("normal"), std::string::npos) << reading.caption;
}

TEST(GlyphReadingTest, AFindingWithoutTheValueIsNoDataNotTheNormalDefault) {
  const auto reading = readGlyph(t::shippedModel(), GlyphBinding(), withIcp({}), false);
  EXPECT_EQ(reading.kind, ReadingKind::kNoData);
}

TEST(GlyphReadingTest, PartialAndPreliminaryExaminationsSaySo) {
  Examination examination = withIcp({{"intensity", Value::number(18)}});
  examination.partial = true;
  examination.partial_reason = "1 observation not imported";
  examination.status = ExaminationStatus::kPreliminary;
  const auto reading = readGlyph(t::shippedModel(), GlyphBinding(), examination, false);
  ASSERT_EQ(reading.kind, ReadingKind::kValue);
  EXPECT_EQ(reading.level, 1);
  EXPECT_NE(reading.caption.find("[partial examination]"), std::string::npos);
  EXPECT_NE(reading.caption.find("[preliminary]"), std::string::npos);
  examination.findings.pop_back();
  const auto missing = readGlyph(t::shippedModel(), GlyphBinding(), examination, false);
  EXPECT_EQ(missing.kind, ReadingKind::kNoData);
  EXPECT_NE(missing.caption.find("[partial examination]"), std::string::npos);
}

TEST(GlyphReadingTest, NoExaminationAndHiddenCategoryDrawNothing) {
  EXPECT_EQ(readGlyph(t::shippedModel(), GlyphBinding(), std::nullopt, false).kind,
            ReadingKind::kNoExamination);
  EXPECT_EQ(readGlyph(t::shippedModel(), GlyphBinding(), t::figurePatient()[0], true).kind,
            ReadingKind::kHidden);
}

TEST(GlyphBindingTest, RejectsWhatCannotFeedAGlyphNamingIt) {
  const EncodingModel& model = t::shippedModel();
  EXPECT_NO_THROW(GlyphBinding().validate(model, kView));
  auto message = [&](GlyphBinding binding) {
    try {
      binding.validate(model, kView);
    } catch (const ConfigError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  GlyphBinding binding;
  binding.category = "intracranial_pressure_x";
  EXPECT_NE(message(binding).find("intracranial_pressure_x"), std::string::npos);
  binding = GlyphBinding();
  binding.property = "volume";
  EXPECT_NE(message(binding).find("volume"), std::string::npos);
  binding = GlyphBinding();
  binding.category = "paresis";  // its intensity is ordinal, derived from the MRC grade
  EXPECT_NE(message(binding).find("numerical"), std::string::npos);
  binding = GlyphBinding();
  binding.design = "";
  EXPECT_NE(message(binding).find("design"), std::string::npos);
  EXPECT_THROW(GlyphBinding().validate(model, "motor_status"), ConfigError);
}

}  // namespace
