#pragma once
// The injectivity requirements of thesis 4.3.2.4 checked on a configuration:
//  - local: M^c injective within each view, M^t injective within each category -> error;
//  - global: the same across views / categories -> warning;
//  - spatial: two categories of a view on the same structure class -> resolved by
//    alternating visualization and the category filter (4.3.3), reported;
//  - property domain: more values than levels -> quantization, reported.

#include <string>
#include <vector>

#include "vicc_anatomy_viz/anatomy_catalog.hpp"
#include "vicc_anatomy_viz/encoding_config.hpp"

namespace vicc_anatomy_viz {

struct QuantizationReport {
  std::string category;
  std::string prop_type;
  std::string visual_variable;
  int values = 0;  ///< displayed values of the domain
  int levels = 0;  ///< visual levels they are mapped to
  std::string message;
};

struct SpatialConflict {
  std::string view;
  std::string category_a;
  std::string category_b;
  std::vector<std::string> shared_classes;
  std::string message;
};

struct InjectivityReport {
  std::vector<std::string> local_violations;  ///< the configuration is rejected
  std::vector<std::string> global_warnings;
  std::vector<SpatialConflict> spatial_conflicts;
  std::vector<QuantizationReport> quantizations;
  std::vector<std::string> level_errors;  ///< levels that cannot be realised (rejected)
};

/// Expects a structurally sound configuration (EncodingConfig::structuralProblems empty).
InjectivityReport checkInjectivity(const EncodingConfig& config);

}  // namespace vicc_anatomy_viz
