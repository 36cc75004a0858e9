# The rviz plugin library (AvatarDisplay; the PatientPanel joins it) and vicc_avatar_snapshot.
# Qt5, OGRE and rviz are found and linked here only: the core, the server and the CLI never
# load them.
find_package(rviz REQUIRED)
find_package(pluginlib REQUIRED)
find_package(Qt5 REQUIRED COMPONENTS Widgets)
find_package(X11 REQUIRED)

add_library(vicc_anatomy_viz_rviz
  include/vicc_anatomy_viz/rviz/avatar_display.hpp
  src/rviz/avatar_display.cpp
  src/rviz/avatar_materials.cpp
  src/rviz/avatar_meshes.cpp
  src/rviz/avatar_visual.cpp
  src/rviz/encoded_status_conversion.cpp
  src/rviz/relief_program.cpp
  src/rviz/renderer_heap.cpp
  src/rviz/screen_overlay.cpp
  src/rviz/see_through_stencil.cpp
  src/rviz/structure_selection.cpp
)
# moc only for the Qt library (not for every later target of the package).
set_target_properties(vicc_anatomy_viz_rviz PROPERTIES AUTOMOC ON)
target_compile_options(vicc_anatomy_viz_rviz PRIVATE ${VICC_WARNINGS})
target_include_directories(vicc_anatomy_viz_rviz SYSTEM PUBLIC ${rviz_INCLUDE_DIRS}
  ${pluginlib_INCLUDE_DIRS})
target_link_libraries(vicc_anatomy_viz_rviz PUBLIC vicc_anatomy_viz_avatar_view
  ${rviz_LIBRARIES} ${pluginlib_LIBRARIES} ${catkin_LIBRARIES} Qt5::Widgets)
add_dependencies(vicc_anatomy_viz_rviz ${catkin_EXPORTED_TARGETS})

install(TARGETS vicc_anatomy_viz_rviz
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})
install(FILES plugin_description.xml DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION})

# vicc_avatar_snapshot: the real rviz with the plugin, off-line (also used by the rostest and
# the FPS benchmark through this library).
add_library(vicc_avatar_snapshot_lib STATIC
  src/tools/vicc_avatar_snapshot_environment.cpp
  src/tools/vicc_avatar_snapshot_options.cpp
  src/tools/vicc_avatar_snapshot_renderer.cpp
)
target_compile_options(vicc_avatar_snapshot_lib PRIVATE ${VICC_WARNINGS})
target_include_directories(vicc_avatar_snapshot_lib PUBLIC src/tools)
target_link_libraries(vicc_avatar_snapshot_lib PUBLIC vicc_anatomy_viz_rviz vicc_common_cli
  ${X11_LIBRARIES})

add_executable(vicc_avatar_snapshot src/tools/vicc_avatar_snapshot.cpp)
target_compile_options(vicc_avatar_snapshot PRIVATE ${VICC_WARNINGS})
target_link_libraries(vicc_avatar_snapshot vicc_avatar_snapshot_lib vicc_anatomy_viz_ros)
install(TARGETS vicc_avatar_snapshot RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})

# Benchmark (bench/avatar): FPS while orbiting the avatar.
add_executable(vicc_avatar_fps bench/avatar/vicc_avatar_fps.cpp)
target_compile_options(vicc_avatar_fps PRIVATE ${VICC_WARNINGS})
target_link_libraries(vicc_avatar_fps vicc_avatar_snapshot_lib vicc_anatomy_viz_ros)
