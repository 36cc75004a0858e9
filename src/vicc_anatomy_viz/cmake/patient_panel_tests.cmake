# The patient panel's logic (GoogleTest).
catkin_add_gtest(vicc_anatomy_viz_panel_logic_test
  test/panel/PanelSettingsTest.cpp
  test/panel/PatientPanelStateTest.cpp
  test/panel/TimelineStateTest.cpp)
target_compile_options(vicc_anatomy_viz_panel_logic_test PRIVATE ${VICC_WARNINGS})
target_link_libraries(vicc_anatomy_viz_panel_logic_test vicc_anatomy_viz_panel_logic gtest_main)

# launch/avatar.launch headless: the sample database and the server's answers.
add_rostest_gtest(avatar_launch_rostest test/panel/avatar_launch.test
  test/panel/AvatarLaunchRostest.cpp)
# The panel plugin (loaded by pluginlib as rviz does) under Xvfb against the same launch file.
find_package(Qt5 REQUIRED COMPONENTS Widgets)
add_rostest_gtest(patient_panel_rostest test/panel/patient_panel.test
  test/panel/PatientPanelRostest.cpp)
target_include_directories(patient_panel_rostest SYSTEM PRIVATE
  ${rviz_INCLUDE_DIRS} ${pluginlib_INCLUDE_DIRS})
target_link_libraries(patient_panel_rostest ${rviz_LIBRARIES} ${pluginlib_LIBRARIES} Qt5::Widgets)
# rviz itself under Xvfb loads the panel from a configuration with a saved selection.
add_rostest_gtest(avatar_rviz_rostest test/panel/avatar_rviz.test test/panel/AvatarRvizRostest.cpp)
foreach(test_target avatar_launch_rostest patient_panel_rostest avatar_rviz_rostest)
  target_compile_options(${test_target} PRIVATE ${VICC_WARNINGS})
  target_link_libraries(${test_target} ${catkin_LIBRARIES})
  add_dependencies(${test_target} patient_status_server vicc_patient vicc_anatomy_viz_rviz_panel
    ${catkin_EXPORTED_TARGETS})
endforeach()
