# GoogleTest suites for the core classes and the CLI, and a rostest for the node's services.
# Test data (configuration, samples) is read from the source tree.
set(VICC_TEST_DEFINITIONS VICC_TEST_PACKAGE_DIR="${CMAKE_CURRENT_SOURCE_DIR}")

catkin_add_gtest(vicc_anatomy_viz_model_test
  test/core/AnatomyCatalogTest.cpp
  test/core/DataModelTest.cpp
  test/core/EncodingConfigTest.cpp
  test/core/InjectivityTest.cpp
  test/core/LevelMappingTest.cpp
  test/core/TimeFormatTest.cpp
  test/core/YamlReadingTest.cpp)
catkin_add_gtest(vicc_anatomy_viz_encoding_test
  test/core/ExaminationValidatorTest.cpp
  test/core/StatusEncoderTest.cpp)
catkin_add_gtest(vicc_anatomy_viz_store_test test/core/RecordStoreTest.cpp)
catkin_add_gtest(vicc_anatomy_viz_exchange_test
  test/core/FhirBundleTest.cpp
  test/core/FhirImportSafetyTest.cpp
  test/core/RecordJsonTest.cpp)
catkin_add_gtest(vicc_anatomy_viz_cli_test test/tools/PatientCliTest.cpp)

foreach(test_target vicc_anatomy_viz_model_test vicc_anatomy_viz_encoding_test
    vicc_anatomy_viz_store_test vicc_anatomy_viz_exchange_test vicc_anatomy_viz_cli_test)
  target_compile_options(${test_target} PRIVATE ${VICC_WARNINGS})
  target_compile_definitions(${test_target} PRIVATE ${VICC_TEST_DEFINITIONS})
  target_link_libraries(${test_target} vicc_anatomy_viz_cli vicc_anatomy_viz_core yaml-cpp gtest_main)
endforeach()

# The node's services against a fresh database file.
add_rostest_gtest(patient_status_server_rostest test/ros/patient_status_server.test
  test/ros/PatientStatusServerRostest.cpp)
target_compile_options(patient_status_server_rostest PRIVATE ${VICC_WARNINGS})
target_compile_definitions(patient_status_server_rostest PRIVATE ${VICC_TEST_DEFINITIONS})
target_link_libraries(patient_status_server_rostest vicc_anatomy_viz_ros ${catkin_LIBRARIES})
add_dependencies(patient_status_server_rostest patient_status_server)
# The node's parameter reader (types, defaults, typos) on a real parameter server.
add_rostest_gtest(server_settings_rostest test/ros/server_settings.test
  test/ros/ServerSettingsRostest.cpp)
target_compile_options(server_settings_rostest PRIVATE ${VICC_WARNINGS})
target_link_libraries(server_settings_rostest vicc_anatomy_viz_ros ${catkin_LIBRARIES})
# The same tests against the node as launch/patient_status_server.launch starts it.
add_rostest(test/ros/patient_status_server_launch.test DEPENDENCIES patient_status_server_rostest)
include(cmake/database_files_tests.cmake)
include(cmake/fhir_conformance.cmake)
include(cmake/fuzz_regression.cmake)

# The avatar model on the default MakeHuman skin (built once per test binary, ~1 s).
catkin_add_gtest(vicc_anatomy_viz_avatar_test
  test/avatar/AvatarManifestTest.cpp
  test/avatar/AvatarModelTest.cpp
  test/avatar/AvatarReportTest.cpp
  test/avatar/DermatomeLabellingTest.cpp)
target_compile_options(vicc_anatomy_viz_avatar_test PRIVATE ${VICC_WARNINGS})
target_compile_definitions(vicc_anatomy_viz_avatar_test PRIVATE ${VICC_TEST_DEFINITIONS})
target_link_libraries(vicc_anatomy_viz_avatar_test vicc_anatomy_viz_avatar gtest_main)

# The avatar's view logic on a synthetic avatar (no rviz, no display).
catkin_add_gtest(vicc_anatomy_viz_avatar_view_test
  test/avatar_view/AlternationTest.cpp
  test/avatar_view/DrawStateTest.cpp
  test/avatar_view/OcclusionTest.cpp
  test/avatar_view/ProceduralTextureTest.cpp
  test/avatar_view/ReliefShadingTest.cpp
  test/avatar_view/RenderBatchesTest.cpp)
target_compile_options(vicc_anatomy_viz_avatar_view_test PRIVATE ${VICC_WARNINGS})
target_link_libraries(vicc_anatomy_viz_avatar_view_test vicc_anatomy_viz_avatar_view gtest_main)

# The AvatarDisplay in the real rviz under Xvfb (xvfb-run is the test's launch-prefix).
add_rostest_gtest(avatar_display_rostest test/rviz/avatar_display.test
  test/rviz/AvatarDisplayRostest.cpp)
target_compile_options(avatar_display_rostest PRIVATE ${VICC_WARNINGS})
target_compile_definitions(avatar_display_rostest PRIVATE ${VICC_TEST_DEFINITIONS})
target_link_libraries(avatar_display_rostest vicc_avatar_snapshot_lib ${catkin_LIBRARIES})
add_dependencies(avatar_display_rostest patient_status_server vicc_anatomy_viz_rviz)

# vicc_avatar_snapshot end to end (starts its own Xvfb and ROS master) and its refusals.
catkin_add_gtest(vicc_avatar_snapshot_test test/rviz/AvatarSnapshotCliTest.cpp)
# run_command.hpp: the workspace's shared test helpers
target_include_directories(vicc_avatar_snapshot_test PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/../../test/common)
target_compile_options(vicc_avatar_snapshot_test PRIVATE ${VICC_WARNINGS})
target_compile_definitions(vicc_avatar_snapshot_test PRIVATE ${VICC_TEST_DEFINITIONS}
  VICC_AVATAR_SNAPSHOT="$<TARGET_FILE:vicc_avatar_snapshot>")
target_link_libraries(vicc_avatar_snapshot_test vicc_anatomy_viz_core Qt5::Gui gtest_main)
add_dependencies(vicc_avatar_snapshot_test vicc_avatar_snapshot vicc_anatomy_viz_rviz)

# The patient panel: its logic, avatar.launch, the plugin under Xvfb.
include(cmake/patient_panel_tests.cmake)
include(cmake/status_glyph_tests.cmake)

# The heap tuning for software rendering (no display needed).
catkin_add_gtest(vicc_anatomy_viz_renderer_heap_test test/rviz/RendererHeapTest.cpp)
target_compile_options(vicc_anatomy_viz_renderer_heap_test PRIVATE ${VICC_WARNINGS})
target_link_libraries(vicc_anatomy_viz_renderer_heap_test vicc_anatomy_viz_rviz gtest_main)

# avatar.launch's launch-prefix of rviz (anti-aliasing true / false / auto).
catkin_add_gtest(vicc_anatomy_viz_rviz_antialiasing_test test/tools/RvizAntialiasingTest.cpp)
target_compile_options(vicc_anatomy_viz_rviz_antialiasing_test PRIVATE ${VICC_WARNINGS})
target_compile_definitions(vicc_anatomy_viz_rviz_antialiasing_test PRIVATE
  VICC_RVIZ_ANTIALIASING_SCRIPT="${CMAKE_CURRENT_SOURCE_DIR}/scripts/rviz_antialiasing"
  VICC_AVATAR_LAUNCH="${CMAKE_CURRENT_SOURCE_DIR}/launch/avatar.launch")
target_include_directories(vicc_anatomy_viz_rviz_antialiasing_test PRIVATE
  ${CMAKE_CURRENT_SOURCE_DIR}/../../test/common)
target_link_libraries(vicc_anatomy_viz_rviz_antialiasing_test gtest_main)
