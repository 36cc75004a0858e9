// Every write is validated against the view; problems name the offending finding.
#include <gtest/gtest.h>

#include "test_support.hpp"
#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/examination_validator.hpp"

namespace vicc_anatomy_viz {
namespace {

using test::figurePatient;
using test::finding;
using test::shippedModel;

Examination examinationOf(std::vector<Finding> findings, std::string patient = "SDH-900") {
  Examination examination;
  examination.patient_id = std::move(patient);
  examination.taken_at_us = 1700000000 * kMicrosPerSecond;  // 2023-11-14T22:13:20Z
  examination.findings = std::move(findings);
  return examination;
}

std::vector<std::string> problemsOf(const Examination& examination,
                                    const std::string& view = "neurological_status_sdh") {
  return ExaminationValidator(shippedModel(), view).problems(examination);
}

void expectSingleProblem(const Finding& bad, const std::string& fragment) {
  const auto problems = problemsOf(examinationOf({bad}));
  ASSERT_EQ(problems.size(), 1u) << fragment;
  EXPECT_NE(problems[0].find(fragment), std::string::npos) << problems[0];
  EXPECT_NE(problems[0].find("patient SDH-900, examination 2023-11-14T22:13:20Z, finding 1 ("),
            std::string::npos)
      << problems[0];
}

TEST(ExaminationValidatorTest, SampleRecordsAreValid) {
  for (const auto& examination : figurePatient()) EXPECT_TRUE(problemsOf(examination).empty());
  for (const auto& examination : test::sampleExaminations("cases.json")) {
    EXPECT_TRUE(problemsOf(examination).empty()) << examination.describe();
  }
}

TEST(ExaminationValidatorTest, ValueOutsideTheDomainIsNamed) {
  expectSingleProblem(
      finding("radicular_pain", "dermatome_L5", Side::kLeft, {{"intensity", Value::number(11)}}),
      "(radicular_pain on dermatome_L5 left): property 'intensity': the value is outside the "
      "domain 0..10");
  expectSingleProblem(finding("paresis", "tibialis_anterior", Side::kRight,
                              {{"muscle_strength", Value::number(6)}}),
                      "property 'muscle_strength': the value is outside the domain 0..5");
  expectSingleProblem(finding("radicular_pain", "dermatome_L5", Side::kLeft,
                              {{"trigger", Value::label("sometimes")}}),
                      "property 'trigger': the value is outside the domain {constant, "
                      "stress}");
  expectSingleProblem(
      finding("t_reflex", "patellar_ligament", Side::kLeft, {{"intensity", Value::label("weak")}}),
      "property 'intensity': the value is not a number (domain 1..5)");
}

TEST(ExaminationValidatorTest, UnknownOrMismatchedStructuresAreNamed) {
  expectSingleProblem(
      finding("radicular_pain", "dermatome_L9", Side::kLeft, {{"intensity", Value::number(3)}}),
      "unknown structure 'dermatome_L9'");
  expectSingleProblem(
      finding("radicular_pain", "patellar_ligament", Side::kLeft,
              {{"intensity", Value::number(3)}}),
      "structure 'patellar_ligament' is a tendon, but 'radicular_pain' refers to dermatome");
  expectSingleProblem(
      finding("radicular_pain", "dermatome_L5", Side::kNone, {{"intensity", Value::number(3)}}),
      "bilateral structure 'dermatome_L5' needs side left or right");
  expectSingleProblem(
      finding("excretion_disorder", "urethra", Side::kLeft, {{"intensity", Value::label("true")}}),
      "side 'left' given for midline structure 'urethra' (use none)");
}

TEST(ExaminationValidatorTest, CategoriesAndPropertiesMustBelongToTheView) {
  expectSingleProblem(
      finding("fever", "dermatome_L5", Side::kLeft, {{"degrees", Value::number(39)}}),
      "category 'fever' is not part of view 'neurological_status_sdh'");
  expectSingleProblem(
      finding("radicular_pain", "dermatome_L5", Side::kLeft, {{"quality", Value::label("dull")}}),
      "unknown property 'quality' for category 'radicular_pain' (known: intensity, trigger)");
  // The motor view has no sensory categories.
  const auto problems =
      problemsOf(examinationOf({finding("sensory_disorder", "dermatome_L5", Side::kLeft,
                                        {{"intensity", Value::number(1)}})}),
                 "motor_status");
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].find("not part of view 'motor_status' (categories: paresis, t_reflex)"),
            std::string::npos);
}

TEST(ExaminationValidatorTest, DerivedValueMustAgreeWithItsSource) {
  expectSingleProblem(
      finding("paresis", "tibialis_anterior", Side::kRight,
              {{"muscle_strength", Value::number(3)}, {"intensity", Value::label("mild")}}),
      "property 'intensity' contradicts the recorded muscle_strength (from which it is derived)");
  EXPECT_TRUE(problemsOf(examinationOf({finding("paresis", "tibialis_anterior", Side::kRight,
                                                {{"muscle_strength", Value::number(3)},
                                                 {"intensity", Value::label("moderate")}})}))
                  .empty());
}

TEST(ExaminationValidatorTest, DuplicatesAndEmptyFindingsAreRejected) {
  const Finding pain =
      finding("radicular_pain", "dermatome_L5", Side::kLeft, {{"intensity", Value::number(3)}});
  auto problems = problemsOf(examinationOf({pain, pain}));
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].find("finding 2 (radicular_pain on dermatome_L5 left): recorded twice"),
            std::string::npos);
  expectSingleProblem(finding("radicular_pain", "dermatome_L5", Side::kLeft, {}),
                      "no property values recorded");
}

TEST(ExaminationValidatorTest, PatientIdsArePseudonymsAndNeverEchoed) {
  const auto problems = problemsOf(examinationOf({}, "Erika Mustermann"));
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].find("patient id may only contain letters, digits"), std::string::npos);
  EXPECT_EQ(problems[0].find("Mustermann"), std::string::npos);
  EXPECT_FALSE(patientIdProblem("").empty());
  EXPECT_FALSE(patientIdProblem(std::string(65, 'a')).empty());
  EXPECT_TRUE(patientIdProblem("SDH-046").empty());
}

TEST(ExaminationValidatorTest, ABatchIsAcceptedWholeOrRejectedWithEveryProblem) {
  const ExaminationValidator validator(shippedModel(), "neurological_status_sdh");
  std::vector<Examination> batch = figurePatient();
  batch[1].findings[1].values["paresthesia"] = Value::number(4);
  batch[0].findings[0].structure = "dermatome_X1";
  try {
    validator.validate(batch);
    FAIL();
  } catch (const ValidationError& e) {
    ASSERT_EQ(e.problems().size(), 2u);
    EXPECT_NE(std::string(e.what()).find("nothing was written"), std::string::npos);
  }
  std::vector<Examination> twice = {figurePatient()[0], figurePatient()[0]};
  EXPECT_THROW(validator.validate(twice), ValidationError);
  const ValidatedBatch ok = validator.validate(figurePatient());
  EXPECT_EQ(ok.examinations().size(), 2u);
  EXPECT_EQ(ok.examinations()[0].view_id, "neurological_status_sdh");
}

TEST(ExaminationValidatorTest, TextValuesAreReadWithTheirPropertyType) {
  const EncodingModel& model = shippedModel();
  EXPECT_EQ(valueFromText(model, "radicular_pain", "intensity", "8"), Value::number(8));
  EXPECT_EQ(valueFromText(model, "paresis", "muscle_strength", "3"), Value::number(3));
  EXPECT_EQ(valueFromText(model, "radicular_pain", "trigger", "stress"), Value::label("stress"));
  EXPECT_EQ(valueFromText(model, "radicular_pain", "intensity", "high"), Value::label("high"));
  EXPECT_EQ(valueFromText(model, "unknown", "x", "4"), Value::label("4"));
}

}  // namespace
}  // namespace vicc_anatomy_viz
