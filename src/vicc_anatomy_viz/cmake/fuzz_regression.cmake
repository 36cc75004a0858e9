# Replays the fuzz seeds and every input under fuzz/regressions/<target>/ through the same
# harness functions run_fuzz.sh fuzzes (built here with the normal compiler, no sanitizers).
# The validator harness needs FuzzedDataProvider.h, a header that ships with clang. It is
# copied on its own: clang's include directory also holds compiler headers g++ must not see.
file(GLOB VICC_CLANG_INCLUDE_DIRS /usr/lib/llvm-*/lib/clang/*/include)
find_file(VICC_FUZZED_DATA_PROVIDER fuzzer/FuzzedDataProvider.h HINTS ${VICC_CLANG_INCLUDE_DIRS})

if(VICC_FUZZED_DATA_PROVIDER)
  set(VICC_FUZZED_DATA_PROVIDER_DIR ${CMAKE_CURRENT_BINARY_DIR}/fuzzed_data_provider)
  configure_file(${VICC_FUZZED_DATA_PROVIDER}
    ${VICC_FUZZED_DATA_PROVIDER_DIR}/fuzzer/FuzzedDataProvider.h COPYONLY)
  catkin_add_gtest(vicc_anatomy_viz_fuzz_regression_test
    test/core/FuzzRegressionTest.cpp
    fuzz/fuzz_model.cpp
    fuzz/fuzz_json_import.cpp
    fuzz/fuzz_fhir_import.cpp
    fuzz/fuzzed_examinations.cpp
    fuzz/fuzz_validator.cpp)
  target_include_directories(vicc_anatomy_viz_fuzz_regression_test SYSTEM PRIVATE
    ${VICC_FUZZED_DATA_PROVIDER_DIR})
  target_include_directories(vicc_anatomy_viz_fuzz_regression_test PRIVATE fuzz)
  target_compile_options(vicc_anatomy_viz_fuzz_regression_test PRIVATE ${VICC_WARNINGS})
  target_compile_definitions(vicc_anatomy_viz_fuzz_regression_test PRIVATE
    ${VICC_TEST_DEFINITIONS} VICC_ANATOMY_VIZ_SOURCE_DIR="${CMAKE_CURRENT_SOURCE_DIR}")
  target_link_libraries(vicc_anatomy_viz_fuzz_regression_test vicc_anatomy_viz_core gtest_main)
else()
  message(WARNING "fuzzer/FuzzedDataProvider.h (clang) not found: "
                  "vicc_anatomy_viz_fuzz_regression_test is not built")
endif()
