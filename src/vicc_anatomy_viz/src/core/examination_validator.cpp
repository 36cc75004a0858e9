#include "vicc_anatomy_viz/examination_validator.hpp"

#include <set>
#include <sstream>
#include <tuple>

#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/time_format.hpp"

namespace vicc_anatomy_viz {

namespace {

std::string listCategories(const View& view) {
  std::ostringstream out;
  for (std::size_t i = 0; i < view.categories.size(); ++i) {
    out << (i ? ", " : "") << view.categories[i].category;
  }
  return out.str();
}

std::string listProperties(const Category& category) {
  std::ostringstream out;
  bool first = true;
  for (const auto& prop : category.props) {
    out << (first ? "" : ", ") << prop.prop_type;
    first = false;
    if (prop.source) out << ", " << prop.source->prop_type;
  }
  return out.str();
}

/// A value of the wrong kind or outside the domain; "" when fine. Messages end up in logs:
/// they name the property and the domain, never the recorded value.
std::string domainProblem(const std::string& prop_type, const Domain& domain, const Value& value) {
  if (domain.type == DataType::kNumerical && !value.isNumber()) {
    return "property '" + prop_type + "': the value is not a number (domain " + domain.describe() +
           ")";
  }
  if (domain.type != DataType::kNumerical && value.isNumber()) {
    return "property '" + prop_type + "': the value is a number, not one of " + domain.describe();
  }
  if (!domain.contains(value)) {
    return "property '" + prop_type + "': the value is outside the domain " + domain.describe();
  }
  return "";
}

}  // namespace

Value valueFromText(const EncodingModel& model, const std::string& category,
                    const std::string& prop_type, const std::string& text) {
  const Category* found = model.config().category(category);
  const Domain* domain = nullptr;
  if (found) {
    if (const Property* prop = found->property(prop_type)) {
      domain = &prop->domain;
    } else if (const Property* derived = found->propertyWithSource(prop_type)) {
      domain = &derived->source->domain;
    }
  }
  if (domain) {
    if (const auto value = domain->parse(text)) return *value;
  }
  return Value::label(text);
}

ExaminationValidator::ExaminationValidator(const EncodingModel& model, const std::string& view_id)
    : model_(model), view_(model.view(view_id)) {}

std::vector<std::string> ExaminationValidator::findingProblems(const Finding& finding) const {
  std::vector<std::string> problems;
  const Category* category = model_.config().category(finding.category);
  if (!view_.contains(finding.category) || !category) {
    problems.push_back("category '" + finding.category + "' is not part of view '" + view_.id +
                       "' (categories: " + listCategories(view_) + ")");
  }
  const AnatomyCatalog& anatomy = model_.anatomy();
  const Structure* structure = anatomy.structure(finding.structure);
  if (!structure) {
    problems.push_back("unknown structure '" + finding.structure + "'");
  } else {
    if (category && !category->refersTo(structure->class_id)) {
      std::ostringstream refs;
      for (std::size_t i = 0; i < category->spatial_refs.size(); ++i) {
        refs << (i ? " or " : "") << category->spatial_refs[i];
      }
      problems.push_back("structure '" + structure->id + "' is a " + structure->class_id +
                         ", but '" + category->id + "' refers to " + refs.str());
    }
    if (!anatomy.sideAllowed(*structure, finding.side)) {
      problems.push_back(
          anatomy.classOf(*structure).laterality == Laterality::kMidline
              ? "side '" + toString(finding.side) + "' given for midline structure '" +
                    structure->id + "' (use none)"
              : "bilateral structure '" + structure->id + "' needs side left or right");
    }
  }
  if (!category) return problems;
  if (finding.values.empty()) problems.push_back("no property values recorded");
  for (const auto& [prop_type, value] : finding.values) {
    if (const Property* prop = category->property(prop_type)) {
      const std::string problem = domainProblem(prop_type, prop->domain, value);
      if (!problem.empty()) problems.push_back(problem);
    } else if (const Property* derived = category->propertyWithSource(prop_type)) {
      const std::string problem = domainProblem(prop_type, derived->source->domain, value);
      if (!problem.empty()) {
        problems.push_back(problem);
        continue;
      }
      // A derived value recorded next to its source must agree with it.
      const auto given = finding.values.find(derived->prop_type);
      const Value expected = derived->source->derive.at(value.toString());
      if (given != finding.values.end() && given->second != expected) {
        problems.push_back("property '" + derived->prop_type + "' contradicts the recorded " +
                           prop_type + " (from which it is derived)");
      }
    } else {
      problems.push_back("unknown property '" + prop_type + "' for category '" + category->id +
                         "' (known: " + listProperties(*category) + ")");
    }
  }
  for (const auto& prop : category->props) {
    const bool given = finding.values.count(prop.prop_type) ||
                       (prop.source && finding.values.count(prop.source->prop_type));
    if (!given && prop.normal.empty()) {
      problems.push_back("property '" + prop.prop_type +
                         "' is missing (it has no normal value to assume)");
    }
  }
  return problems;
}

std::vector<std::string> ExaminationValidator::problems(const Examination& examination) const {
  std::vector<std::string> problems;
  const std::string id_problem = patientIdProblem(examination.patient_id);
  const std::string exam_name = id_problem.empty()
                                    ? examination.describe()
                                    : "examination " + formatTimestamp(examination.taken_at_us);
  if (!id_problem.empty()) problems.push_back(exam_name + ": " + id_problem);
  // Our exchange formats write times as ISO 8601 with four-digit years: a time outside them
  // could be stored but never exported faithfully.
  if (parseTimestamp(formatTimestamp(examination.taken_at_us)) != examination.taken_at_us) {
    problems.push_back(exam_name + ": time cannot be written as ISO 8601 (years 0000-9999)");
  }
  std::set<std::tuple<std::string, std::string, Side>> seen;
  for (std::size_t i = 0; i < examination.findings.size(); ++i) {
    const Finding& finding = examination.findings[i];
    const std::string where =
        exam_name + ", finding " + std::to_string(i + 1) + " (" + finding.describe() + "): ";
    for (const auto& problem : findingProblems(finding)) problems.push_back(where + problem);
    if (!seen.emplace(finding.category, finding.structure, finding.side).second) {
      problems.push_back(where + "recorded twice in the same examination");
    }
  }
  return problems;
}

ValidatedBatch ExaminationValidator::validate(std::vector<Examination> examinations) const {
  std::vector<std::string> problems;
  std::set<std::pair<std::string, TimestampUs>> seen;
  for (auto& examination : examinations) {
    examination.view_id = view_.id;
    const auto found = this->problems(examination);
    problems.insert(problems.end(), found.begin(), found.end());
    if (!seen.emplace(examination.patient_id, examination.taken_at_us).second &&
        patientIdProblem(examination.patient_id).empty()) {
      problems.push_back(examination.describe() + ": appears twice in the batch");
    }
  }
  if (!problems.empty()) throw ValidationError(problems);
  return ValidatedBatch(std::move(examinations));
}

}  // namespace vicc_anatomy_viz
