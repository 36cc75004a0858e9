# ROS-free rig simulator: analytic scenes, keyframe trajectories, ToF and IMU models.
add_library(vicc_tracking_sim
  src/sim/rig_simulator.cpp
  src/sim/scenario.cpp
  src/sim/scene.cpp
  src/sim/trajectory.cpp
  src/sim/visible_surface.cpp
  src/sim/extrapolation_error.cpp
)
target_compile_options(vicc_tracking_sim PRIVATE ${VICC_WARNINGS})
# Named scenarios come from share/vicc_tracking/config (vicc_paths), in devel and install.
target_link_libraries(vicc_tracking_sim vicc_tracking_core vicc_paths ${OpenCV_LIBS} yaml-cpp)

if(CATKIN_ENABLE_TESTING)
  catkin_add_gtest(vicc_tracking_sim_test
    test/sim/SceneTest.cpp
    test/sim/TrajectoryTest.cpp
    test/sim/RigSimulatorTest.cpp
    test/sim/ScenarioTest.cpp
    test/sim/VisibleSurfaceTest.cpp
    test/sim/TrackerTest.cpp
    test/sim/TrackerTuningTest.cpp
    test/sim/ExtrapolationErrorTest.cpp)
  target_compile_options(vicc_tracking_sim_test PRIVATE ${VICC_WARNINGS})
  target_link_libraries(vicc_tracking_sim_test vicc_tracking_sim gtest_main)
endif()

# R against the frame interval on the scenarios (docs/imu_noise.md).
add_executable(vicc_extrapolation_error src/tools/vicc_extrapolation_error.cpp)
target_compile_options(vicc_extrapolation_error PRIVATE ${VICC_WARNINGS})
target_link_libraries(vicc_extrapolation_error vicc_tracking_sim vicc_common_cli)
