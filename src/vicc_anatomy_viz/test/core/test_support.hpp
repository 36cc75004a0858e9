#pragma once
// Shared fixtures of the core tests: the shipped configuration, the sample records and
// temporary directories for real database files.

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "vicc_anatomy_viz/encoding_model.hpp"
#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/record_json.hpp"

namespace vicc_anatomy_viz::test {

inline std::string packagePath(const std::string& relative) {
  return std::string(VICC_TEST_PACKAGE_DIR) + "/" + relative;
}

inline std::string encodingConfigPath() {
  return packagePath("config/encoding/neurological_status.yaml");
}
inline std::string anatomyConfigPath() { return packagePath("config/anatomy/structures.yaml"); }

inline const EncodingModel& shippedModel() {
  static const EncodingModel model = EncodingModel::load(encodingConfigPath(), anatomyConfigPath());
  return model;
}

inline const AnatomyCatalog& shippedAnatomy() { return shippedModel().anatomy(); }

/// The shipped encoding configuration as a YAML tree, to derive broken variants from.
inline YAML::Node shippedConfigYaml() { return YAML::LoadFile(encodingConfigPath()); }

/// Builds a model from a (modified) YAML tree with the shipped anatomy.
inline EncodingModel modelFrom(const YAML::Node& root) {
  return EncodingModel(EncodingConfig::fromYamlText(YAML::Dump(root), "test-config.yaml"),
                       AnatomyCatalog::load(anatomyConfigPath()));
}

/// The message a configuration is rejected with; a test failure if it is accepted.
inline std::string rejection(const YAML::Node& root) {
  try {
    modelFrom(root);
  } catch (const ConfigError& e) {
    return e.what();
  }
  ADD_FAILURE() << "configuration accepted";
  return "";
}

/// The YAML node of a category or view by id.
inline YAML::Node entryWithId(YAML::Node list, const std::string& id) {
  for (std::size_t i = 0; i < list.size(); ++i) {
    if (list[i]["id"].as<std::string>() == id) return list[i];
  }
  throw std::runtime_error("no entry " + id);
}

inline std::vector<Examination> sampleExaminations(const std::string& file) {
  const std::string path = packagePath("data/samples/" + file);
  return examinationsFromJson(parseJsonText(readTextFile(path), path), "json");
}

/// Thesis Fig. 4.6: [0] pre-operative, [1] post-operative.
inline std::vector<Examination> figurePatient() {
  return sampleExaminations("fig4_6_patient.json");
}

inline Finding finding(const std::string& category, const std::string& structure, Side side,
                       std::map<std::string, Value> values) {
  Finding out;
  out.category = category;
  out.structure = structure;
  out.side = side;
  out.values = std::move(values);
  return out;
}

/// A fresh directory removed with all its content at the end of the test.
class TempDir {
 public:
  TempDir() {
    std::string pattern =
        (std::filesystem::temp_directory_path() / "vicc_anatomy_viz_test_XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
    path_ = pattern;
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

inline std::string fileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

/// The kind of StoreError an action throws (and its message); a test failure if none.
inline StoreError::Kind storeErrorKind(const std::function<void()>& action,
                                       std::string* message = nullptr) {
  try {
    action();
  } catch (const StoreError& e) {
    if (message) *message = e.what();
    return e.kind();
  }
  ADD_FAILURE() << "no StoreError";
  return StoreError::Kind::kOther;
}

inline void writeFile(const std::string& path, const std::string& content) {
  std::ofstream(path, std::ios::binary) << content;
}

}  // namespace vicc_anatomy_viz::test
