#pragma once
// Examinations drawn from fuzzer bytes: names mostly from the model (so that many pass
// validation and reach the encoder), sometimes arbitrary text; values in and around the
// domains and anywhere in int; times in and outside the ISO 8601 years.

#include <string>
#include <vector>

#include <fuzzer/FuzzedDataProvider.h>

#include "vicc_anatomy_viz/encoding_model.hpp"
#include "vicc_anatomy_viz/patient_record.hpp"

namespace vicc_anatomy_viz::fuzz {

class FuzzedExaminations {
 public:
  FuzzedExaminations(const EncodingModel& model, FuzzedDataProvider& data);

  std::string viewId();
  std::vector<Examination> examinations();

 private:
  Examination examination();
  Finding finding();
  Value value(const Domain* domain);
  TimestampUs time();
  /// One of `names`, or (about one time in eight) arbitrary text.
  std::string nameFrom(const std::vector<std::string>& names);
  std::string arbitraryText() { return data_.ConsumeRandomLengthString(24); }

  const EncodingModel& model_;
  FuzzedDataProvider& data_;
  std::vector<std::string> view_ids_, category_ids_, structure_ids_;
};

}  // namespace vicc_anatomy_viz::fuzz
