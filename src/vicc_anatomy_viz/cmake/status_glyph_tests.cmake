# The status glyph's logic (reading, billboard quads, the ICP configuration) and, under Xvfb,
# the glyph above the avatar's head in the real rviz with the real patient and glyph servers.
catkin_add_gtest(vicc_anatomy_viz_status_glyph_test
  test/status_glyph/GlyphBillboardTest.cpp
  test/status_glyph/GlyphReadingTest.cpp)
target_compile_options(vicc_anatomy_viz_status_glyph_test PRIVATE ${VICC_WARNINGS})
target_compile_definitions(vicc_anatomy_viz_status_glyph_test PRIVATE ${VICC_TEST_DEFINITIONS})
target_link_libraries(vicc_anatomy_viz_status_glyph_test vicc_anatomy_viz_status_glyph yaml-cpp
  gtest_main)

add_rostest_gtest(status_glyph_rostest test/status_glyph/status_glyph.test
  test/status_glyph/StatusGlyphRostest.cpp)
target_compile_options(status_glyph_rostest PRIVATE ${VICC_WARNINGS})
target_compile_definitions(status_glyph_rostest PRIVATE ${VICC_TEST_DEFINITIONS})
target_link_libraries(status_glyph_rostest vicc_avatar_snapshot_lib ${catkin_LIBRARIES})
add_dependencies(status_glyph_rostest patient_status_server status_glyph_markers)
# The glyph server is another package's node: built first when the workspace has it.
if(TARGET glyph_server)
  add_dependencies(status_glyph_rostest glyph_server)
endif()
