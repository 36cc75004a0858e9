# The patient panel's logic (GoogleTest).
catkin_add_gtest(vicc_anatomy_viz_panel_logic_test
  test/panel/PanelSettingsTest.cpp
  test/panel/PatientPanelStateTest.cpp
  test/panel/TimelineStateTest.cpp)
target_compile_options(vicc_anatomy_viz_panel_logic_test PRIVATE ${VICC_WARNINGS})
target_link_libraries(vicc_anatomy_viz_panel_logic_test vicc_anatomy_viz_panel_logic gtest_main)
