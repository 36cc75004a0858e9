# The SQLite file layer: open modes, private files, companion paths, backup and restore.
catkin_add_gtest(vicc_anatomy_viz_database_files_test
  test/core/DatabaseFilesTest.cpp
  test/core/DatabaseBackupTest.cpp
  test/core/SqliteConnectionTest.cpp)
target_compile_options(vicc_anatomy_viz_database_files_test PRIVATE ${VICC_WARNINGS})
target_compile_definitions(vicc_anatomy_viz_database_files_test PRIVATE ${VICC_TEST_DEFINITIONS})
target_link_libraries(vicc_anatomy_viz_database_files_test vicc_anatomy_viz_core gtest_main
  pthread)

# Timing of PRAGMA synchronous FULL against NORMAL for bench/patient_status/durability.md
# (not a test; built with the tests so that it stays out of the installed tools).
add_executable(vicc_durability_bench src/tools/vicc_durability_bench.cpp)
target_compile_options(vicc_durability_bench PRIVATE ${VICC_WARNINGS})
target_link_libraries(vicc_durability_bench vicc_anatomy_viz_core vicc_common_cli)

# The command lines of vicc_avatar_model and the bench tools (vicc_common's parser).
catkin_add_gtest(vicc_anatomy_viz_tool_usage_test test/tools/ToolUsageTest.cpp)
# run_command.hpp: the workspace's shared test helpers
target_include_directories(vicc_anatomy_viz_tool_usage_test PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/../../test/common)
target_compile_options(vicc_anatomy_viz_tool_usage_test PRIVATE ${VICC_WARNINGS})
target_compile_definitions(vicc_anatomy_viz_tool_usage_test PRIVATE
  VICC_AVATAR_MODEL_TOOL="$<TARGET_FILE:vicc_avatar_model>"
  VICC_PATIENT_BENCH_TOOL="$<TARGET_FILE:vicc_patient_bench>"
  VICC_DURABILITY_BENCH_TOOL="$<TARGET_FILE:vicc_durability_bench>"
  VICC_AVATAR_FPS_TOOL="$<TARGET_FILE:vicc_avatar_fps>")
target_link_libraries(vicc_anatomy_viz_tool_usage_test gtest_main)
add_dependencies(vicc_anatomy_viz_tool_usage_test vicc_avatar_model vicc_patient_bench
  vicc_durability_bench vicc_avatar_fps)
