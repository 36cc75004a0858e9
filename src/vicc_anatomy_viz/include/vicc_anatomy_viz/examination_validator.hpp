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

class ExaminationValidator {
 public:
  /// Throws ConfigError when the view is unknown.
  ExaminationValidator(const EncodingModel& model, const std::string& view_id);

  /// Every problem of one examination, each naming the examination and the finding.
  std::vector<std::string> problems(const Examination& examination) const;
  /// Validates all examinations (and that no two share patient and time); sets their view.
  /// Throws ValidationError listing every problem.
  ValidatedBatch validate(std::vector<Examination> examinations) const;

 private:
  std::vector<std::string> findingProblems(const Finding& finding) const;

  const EncodingModel& model_;
  const View& view_;
};

}  // namespace vicc_anatomy_viz
