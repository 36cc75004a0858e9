# Unit tests of the tracking core against analytic cases. Scenes are rendered with the
# simulator library (noise-free) where a test needs real geometry.
if(CATKIN_ENABLE_TESTING)
  catkin_add_gtest(vicc_tracking_core_test
    test/core/EkfTest.cpp
    test/core/InitStrategyTest.cpp
    test/core/IcpTest.cpp
    test/core/DepthPreprocessingTest.cpp
    test/core/CameraModelTest.cpp
    test/core/ImuNoiseTest.cpp
    test/core/ImuSynchronizerTest.cpp
    test/core/StillPhaseTest.cpp)
  target_compile_options(vicc_tracking_core_test PRIVATE ${VICC_WARNINGS})
  target_compile_definitions(vicc_tracking_core_test PRIVATE
    VICC_TRACKING_CONFIG_DIR="${CMAKE_CURRENT_SOURCE_DIR}/config")
  target_link_libraries(vicc_tracking_core_test vicc_tracking_core vicc_tracking_sim gtest_main)
endif()
