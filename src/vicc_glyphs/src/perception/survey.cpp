#include "vicc_glyphs/perception/survey.hpp"

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

namespace vicc_glyphs::perception {
namespace {

const char* const kHeader = "stimulus,perceived,experiment,second_stimulus";

std::vector<std::string> splitFields(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream stream(line);
  for (std::string field; std::getline(stream, field, ',');) fields.push_back(field);
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

std::string trimmed(const std::string& text) {
  const size_t first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

double parseNumber(const std::string& text, int line, const char* column) {
  size_t used = 0;
  double value = NAN;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !std::isfinite(value)) {
    throw SurveyFileError("line " + std::to_string(line) + ": " + column +
                          " must be a finite number, got '" + text + "'");
  }
  return value;
}

}  // namespace

std::optional<ExperimentKind> experimentKind(const std::string& name) {
  using V = VisualVariable;
  static const std::map<std::string, ExperimentKind> kinds{
      {"Ampl1", {V::GeometricAmplitude, std::nullopt}},
      {"Ampl2", {V::GeometricAmplitude, std::nullopt}},
      {"Freq1", {V::GeometricFrequency, std::nullopt}},
      {"Freq2", {V::GeometricFrequency, std::nullopt}},
      {"ColAmpl1", {V::ColourAmplitude, std::nullopt}},
      {"ColAmpl2", {V::ColourAmplitude, std::nullopt}},
      {"ColFreq1", {V::ColourFrequency, std::nullopt}},
      {"ColFreq2", {V::ColourFrequency, std::nullopt}},
      {"SawtAmpl", {V::GeometricAmplitude, Waveform::Sawtooth}},
      {"RectAmpl", {V::GeometricAmplitude, Waveform::Rectangle}},
      {"SawtFreq", {V::GeometricFrequency, Waveform::Sawtooth}},
      {"RectFreq", {V::GeometricFrequency, Waveform::Rectangle}},
  };
  const auto found = kinds.find(name);
  if (found == kinds.end()) return std::nullopt;
  return found->second;
}

std::vector<SurveyAnswer> parseSurveyCsv(const std::string& text) {
  std::istringstream lines(text);
  std::string line;
  if (!std::getline(lines, line) || trimmed(line) != kHeader) {
    throw SurveyFileError(std::string("line 1: the header must be '") + kHeader + "'");
  }
  std::vector<SurveyAnswer> answers;
  for (int number = 2; std::getline(lines, line); ++number) {
    if (trimmed(line).empty()) continue;
    const std::vector<std::string> fields = splitFields(line);
    if (fields.size() != 4) {
      throw SurveyFileError("line " + std::to_string(number) + ": expected 4 fields, got " +
                            std::to_string(fields.size()));
    }
    SurveyAnswer answer;
    answer.line = number;
    answer.stimulus = parseNumber(trimmed(fields[0]), number, "stimulus");
    answer.perceived = parseNumber(trimmed(fields[1]), number, "perceived");
    answer.experiment = trimmed(fields[2]);
    if (!experimentKind(answer.experiment)) {
      throw SurveyFileError("line " + std::to_string(number) + ": unknown experiment '" +
                            answer.experiment + "' (Table 6.2 names, e.g. Ampl1, ColFreq2)");
    }
    if (!trimmed(fields[3]).empty()) {
      answer.second_stimulus = parseNumber(trimmed(fields[3]), number, "second_stimulus");
    }
    answers.push_back(answer);
  }
  return answers;
}

std::vector<SurveyAnswer> loadSurveyCsv(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw SurveyFileError("cannot read survey file " + path);
  std::ostringstream text;
  text << file.rdbuf();
  try {
    return parseSurveyCsv(text.str());
  } catch (const SurveyFileError& e) {
    throw SurveyFileError(path + ": " + e.what());
  }
}

}  // namespace vicc_glyphs::perception
