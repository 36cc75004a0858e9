#include "fuzzed_examinations.hpp"

#include "fuzz_targets.hpp"

namespace vicc_anatomy_viz::fuzz {

namespace {

constexpr std::size_t kMaxExaminations = 4;
constexpr std::size_t kMaxFindings = 8;
constexpr std::size_t kMaxValues = 4;
// 1900-01-01T00:00:00Z .. 9999-12-31T23:59:59Z, the years parseTimestamp reads.
constexpr std::int64_t kFirstSecond = -2208988800;
constexpr std::int64_t kLastSecond = 253402300799;

/// The names a finding of `category` may record values under, with their domains.
std::vector<std::pair<std::string, const Domain*>> recordableProperties(const Category& category) {
  std::vector<std::pair<std::string, const Domain*>> out;
  for (const Property& prop : category.props) {
    out.emplace_back(prop.prop_type, &prop.domain);
    if (prop.source) out.emplace_back(prop.source->prop_type, &prop.source->domain);
  }
  return out;
}

}  // namespace

FuzzedExaminations::FuzzedExaminations(const EncodingModel& model, FuzzedDataProvider& data)
    : model_(model), data_(data) {
  for (const View& view : model.config().views) view_ids_.push_back(view.id);
  for (const Category& category : model.config().categories) category_ids_.push_back(category.id);
  for (const Structure& structure : model.anatomy().structures()) {
    structure_ids_.push_back(structure.id);
  }
}

std::string FuzzedExaminations::nameFrom(const std::vector<std::string>& names) {
  if (names.empty() || data_.ConsumeIntegralInRange(0, 7) == 0) return arbitraryText();
  return names[data_.ConsumeIntegralInRange<std::size_t>(0, names.size() - 1)];
}

std::string FuzzedExaminations::viewId() {
  return view_ids_.at(data_.ConsumeIntegralInRange<std::size_t>(0, view_ids_.size() - 1));
}

std::vector<Examination> FuzzedExaminations::examinations() {
  std::vector<Examination> out(data_.ConsumeIntegralInRange<std::size_t>(1, kMaxExaminations));
  for (Examination& examination : out) examination = this->examination();
  return out;
}

Examination FuzzedExaminations::examination() {
  Examination examination;
  examination.patient_id = nameFrom({"SDH-046", "SDH-101", "P-1"});
  examination.source = "fuzz";
  setTakenAt(examination, time());
  const auto count = data_.ConsumeIntegralInRange<std::size_t>(0, kMaxFindings);
  for (std::size_t i = 0; i < count && data_.remaining_bytes() > 0; ++i) {
    examination.findings.push_back(finding());
  }
  return examination;
}

TimestampUs FuzzedExaminations::time() {
  switch (data_.ConsumeIntegralInRange(0, 3)) {
    case 0:
      return data_.ConsumeIntegral<TimestampUs>();
    case 1:  // a few days around the same time (with fractions), so examinations can coincide
      return (1678091400 + data_.ConsumeIntegralInRange(0, 3) * 86400) * kMicrosPerSecond +
             data_.ConsumeIntegralInRange(0, 2) * 500000;
    default:
      return data_.ConsumeIntegralInRange(kFirstSecond * kMicrosPerSecond,
                                          kLastSecond * kMicrosPerSecond + kMicrosPerSecond - 1);
  }
}

Finding FuzzedExaminations::finding() {
  Finding finding;
  finding.category = nameFrom(category_ids_);
  finding.structure = nameFrom(structure_ids_);
  finding.side = data_.PickValueInArray({Side::kLeft, Side::kRight, Side::kNone});
  const Category* category = model_.config().category(finding.category);
  const auto properties = category ? recordableProperties(*category)
                                   : std::vector<std::pair<std::string, const Domain*>>{};
  const auto count = data_.ConsumeIntegralInRange<std::size_t>(0, kMaxValues);
  for (std::size_t i = 0; i < count; ++i) {
    const bool known = !properties.empty() && data_.ConsumeIntegralInRange(0, 7) != 0;
    const auto& [prop_type, domain] =
        known ? properties[data_.ConsumeIntegralInRange<std::size_t>(0, properties.size() - 1)]
              : std::pair<std::string, const Domain*>{arbitraryText(), nullptr};
    finding.values[prop_type] = value(domain);
  }
  return finding;
}

Value FuzzedExaminations::value(const Domain* domain) {
  switch (data_.ConsumeIntegralInRange(0, 4)) {
    case 0:
      return Value::number(data_.ConsumeIntegral<int>());
    case 1:
      return Value::label(data_.PickValueInArray({"true", "false"}));
    case 2:
      return Value::label(arbitraryText());
    default:
      if (domain && !domain->labels.empty()) {
        return Value::label(domain->labels[data_.ConsumeIntegralInRange<std::size_t>(
            0, domain->labels.size() - 1)]);
      }
      return Value::number(data_.ConsumeIntegralInRange(-2, 12));
  }
}

}  // namespace vicc_anatomy_viz::fuzz
