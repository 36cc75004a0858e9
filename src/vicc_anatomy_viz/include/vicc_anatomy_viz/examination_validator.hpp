#pragma once
// Validation of examinations against a view before anything is written: unknown category or
// structure, wrong structure class or side, values outside their domain, inconsistent derived
// values, duplicates. A batch with one bad item is rejected whole.

#include <string>
#include <vector>

#include "vicc_anatomy_viz/encoding_model.hpp"
#include "vicc_anatomy_viz/patient_record.hpp"

namespace vicc_anatomy_viz {

/// Examinations that passed validation; only the validator can make one, so the store can
/// only write validated data.
class ValidatedBatch {
 public:
  const std::vector<Examination>& examinations() const { return examinations_; }

 private:
  friend class ExaminationValidator;
  explicit ValidatedBatch(std::vector<Examination> examinations)
      : examinations_(std::move(examinations)) {}
  std::vector<Examination> examinations_;
};

/// Reads a value given as text (service requests, command lines) with the type of the named
/// property (or of the property it is the recorded source of). Text that does not fit the
/// type is kept as a label, so that validation reports it by name.
Value valueFromText(const EncodingModel& model, const std::string& category,
                    const std::string& prop_type, const std::string& text);

class ExaminationValidator {
 public:
  /// Throws ConfigError when the view is unknown.
  ExaminationValidator(const EncodingModel& model, const std::string& view_id);

  /// Every problem of one examination, each naming the examination and the finding.
  std::vector<std::string> problems(const Examination& examination) const;
  /// The problems of one finding on its own (category, structure, side, values).
  std::vector<std::string> findingProblems(const Finding& finding) const;
  /// Validates all examinations (and that no two share patient and time); sets their view.
  /// Throws ValidationError listing every problem.
  ValidatedBatch validate(std::vector<Examination> examinations) const;

 private:
  const EncodingModel& model_;
  const View& view_;
};

}  // namespace vicc_anatomy_viz
