# The SQLite file layer: open modes, private files, companion paths, backup and restore.
catkin_add_gtest(vicc_anatomy_viz_database_files_test
  test/core/DatabaseFilesTest.cpp
  test/core/DatabaseBackupTest.cpp
  test/core/SqliteConnectionTest.cpp)
target_compile_options(vicc_anatomy_viz_database_files_test PRIVATE ${VICC_WARNINGS})
target_compile_definitions(vicc_anatomy_viz_database_files_test PRIVATE ${VICC_TEST_DEFINITIONS})
target_link_libraries(vicc_anatomy_viz_database_files_test vicc_anatomy_viz_core gtest_main
  pthread)
