#pragma once
// Our FHIR R4 CodeSystem resources, generated from the loaded encoding model: the property
// codes "<category>.<property>", the value codes of nominal and ordinal properties and the
// anatomy structure codes, with the urls the export uses (fhir_bundle.hpp).

#include <nlohmann/json.hpp>

#include "vicc_anatomy_viz/encoding_model.hpp"

namespace vicc_anatomy_viz {

/// A Bundle of type collection with the three CodeSystem resources (status active,
/// content complete).
nlohmann::json codeSystemResources(const EncodingModel& model);

}  // namespace vicc_anatomy_viz
