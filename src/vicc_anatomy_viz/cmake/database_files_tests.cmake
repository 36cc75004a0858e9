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
target_link_libraries(vicc_durability_bench vicc_anatomy_viz_core)
