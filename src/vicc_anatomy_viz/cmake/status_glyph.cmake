# Status glyphs above the avatar (issue 15): a measured value of the selected examination
# (intracranial pressure) rendered by the glyph server and shown as a MarkerArray of
# flat-coloured quads. The logic is ROS- and Qt-free; the node is a thin adapter.
add_library(vicc_anatomy_viz_status_glyph
  src/status_glyph/glyph_billboard.cpp
  src/status_glyph/glyph_reading.cpp
)
target_compile_options(vicc_anatomy_viz_status_glyph PRIVATE ${VICC_WARNINGS})
target_link_libraries(vicc_anatomy_viz_status_glyph PUBLIC vicc_anatomy_viz_core Eigen3::Eigen)

add_executable(status_glyph_markers
  src/nodes/status_glyph_markers_node.cpp
  src/ros/status_glyph_markers.cpp
)
target_compile_options(status_glyph_markers PRIVATE ${VICC_WARNINGS})
target_link_libraries(status_glyph_markers vicc_anatomy_viz_status_glyph vicc_anatomy_viz_ros
  vicc_anatomy_viz_avatar ${catkin_LIBRARIES})
add_dependencies(status_glyph_markers ${catkin_EXPORTED_TARGETS})

install(TARGETS vicc_anatomy_viz_status_glyph status_glyph_markers
  RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION}
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})
