# The glyph server (ROS node + nodelet) on the designs, the renderer and the image adapter.
# Its link line has no raster import: vicc_glyphs_design links vicc_glyphs_formats only, so
# potrace (GPL) is not part of the server.
if(NOT TARGET vicc_glyphs_design OR NOT TARGET vicc_glyphs_ros)
  return()
endif()

add_library(vicc_glyphs_server src/ros/glyph_server.cpp)
target_compile_options(vicc_glyphs_server PRIVATE ${VICC_WARNINGS})
# Default designs and perception model: share/vicc_glyphs (vicc_paths), in devel and install.
target_link_libraries(vicc_glyphs_server vicc_glyphs_design vicc_glyphs_ros vicc_glyphs_render
  vicc_paths vicc_common_ros_params ${catkin_LIBRARIES})
add_dependencies(vicc_glyphs_server ${catkin_EXPORTED_TARGETS})

add_executable(glyph_server src/ros/glyph_server_node.cpp)
target_compile_options(glyph_server PRIVATE ${VICC_WARNINGS})
target_link_libraries(glyph_server vicc_glyphs_server ${catkin_LIBRARIES})

add_library(vicc_glyphs_server_nodelet src/ros/glyph_server_nodelet.cpp)
target_compile_options(vicc_glyphs_server_nodelet PRIVATE ${VICC_WARNINGS})
target_link_libraries(vicc_glyphs_server_nodelet vicc_glyphs_server ${catkin_LIBRARIES})

install(TARGETS vicc_glyphs_server vicc_glyphs_server_nodelet glyph_server
  RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION}
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})
install(FILES nodelet_plugins.xml DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION})

if(CATKIN_ENABLE_TESTING)
  find_package(rostest REQUIRED)
  add_rostest_gtest(glyph_server_rostest test/ros/glyph_server.test test/ros/GlyphServerRostest.cpp)
  target_compile_options(glyph_server_rostest PRIVATE ${VICC_WARNINGS})
  target_link_libraries(glyph_server_rostest vicc_glyphs_server ${catkin_LIBRARIES})
  add_dependencies(glyph_server_rostest glyph_server ${catkin_EXPORTED_TARGETS})
  add_rostest(test/ros/glyph_server_nodelet.test
    DEPENDENCIES glyph_server_rostest vicc_glyphs_server_nodelet)
endif()
