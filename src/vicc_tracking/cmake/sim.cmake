# ROS-free rig simulator: analytic scenes, keyframe trajectories, ToF and IMU models.
add_library(vicc_tracking_sim
  src/sim/rig_simulator.cpp
  src/sim/scenario.cpp
  src/sim/scene.cpp
  src/sim/trajectory.cpp
  src/sim/visible_surface.cpp
)
target_compile_options(vicc_tracking_sim PRIVATE ${VICC_WARNINGS})
target_compile_definitions(vicc_tracking_sim PRIVATE
  VICC_SCENARIO_DIR="${CMAKE_CURRENT_SOURCE_DIR}/config/scenarios")
target_link_libraries(vicc_tracking_sim vicc_tracking_core ${OpenCV_LIBS} yaml-cpp)

if(CATKIN_ENABLE_TESTING)
  catkin_add_gtest(vicc_tracking_sim_test
    test/sim/SceneTest.cpp
    test/sim/TrajectoryTest.cpp
    test/sim/RigSimulatorTest.cpp
    test/sim/ScenarioTest.cpp
    test/sim/VisibleSurfaceTest.cpp
    test/sim/TrackerTest.cpp)
  target_compile_options(vicc_tracking_sim_test PRIVATE ${VICC_WARNINGS})
  target_link_libraries(vicc_tracking_sim_test vicc_tracking_sim gtest_main)
endif()
