# The patient panel (thesis 4.4.1, Fig. 4.7A): a Qt-free logic library (timeline, category
# filter, patient list, configuration) and the rviz::Panel plugin in a library of its own, so
# that Qt and rviz stay out of the core, the server and the CLI. Its plugin_description.xml entry
# sits next to the AvatarDisplay's (rviz_plugins.cmake installs the file).
add_library(vicc_anatomy_viz_panel_logic
  src/panel_logic/category_filter_state.cpp
  src/panel_logic/panel_settings.cpp
  src/panel_logic/patient_list_state.cpp
  src/panel_logic/patient_panel_state.cpp
  src/panel_logic/timeline_state.cpp
)
target_compile_options(vicc_anatomy_viz_panel_logic PRIVATE ${VICC_WARNINGS})
target_link_libraries(vicc_anatomy_viz_panel_logic PUBLIC vicc_anatomy_viz_core)

find_package(rviz REQUIRED)
find_package(pluginlib REQUIRED)
find_package(Qt5 REQUIRED COMPONENTS Core Widgets)

add_library(vicc_anatomy_viz_rviz_panel
  include/vicc_anatomy_viz/rviz/patient_panel.hpp
  include/vicc_anatomy_viz/rviz/patient_panel_client.hpp
  src/rviz/patient_panel.cpp
  src/rviz/patient_panel_client.cpp
  src/rviz/patient_panel_widgets.cpp
)
set_target_properties(vicc_anatomy_viz_rviz_panel PROPERTIES AUTOMOC ON)
target_include_directories(vicc_anatomy_viz_rviz_panel SYSTEM PRIVATE
  ${rviz_INCLUDE_DIRS} ${pluginlib_INCLUDE_DIRS})
target_compile_options(vicc_anatomy_viz_rviz_panel PRIVATE ${VICC_WARNINGS})
target_link_libraries(vicc_anatomy_viz_rviz_panel PUBLIC vicc_anatomy_viz_panel_logic
  ${rviz_LIBRARIES} ${pluginlib_LIBRARIES} ${catkin_LIBRARIES} Qt5::Widgets)
add_dependencies(vicc_anatomy_viz_rviz_panel ${catkin_EXPORTED_TARGETS})

install(TARGETS vicc_anatomy_viz_panel_logic vicc_anatomy_viz_rviz_panel
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})
install(DIRECTORY rviz DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION})
install(PROGRAMS scripts/avatar_sample_db scripts/rviz_antialiasing DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION}/scripts)
