# Perception and quantization model of periodic contour modifications (thesis 6.1): stimulus
# scales, Stevens power functions, quantization levels, size transfer, the model file.
# ROS-free: yaml-cpp only.
find_package(yaml-cpp REQUIRED)

add_library(vicc_glyphs_perception
  src/perception/visual_variable.cpp
  src/perception/stevens_power_function.cpp
  src/perception/stimulus_scale.cpp
  src/perception/perception_model.cpp
  src/perception/perception_model_yaml.cpp
)
target_compile_options(vicc_glyphs_perception PRIVATE ${VICC_WARNINGS})
target_link_libraries(vicc_glyphs_perception yaml-cpp)

# Deriving the model from survey answers: outliers, Stevens fit (Ceres), level distributions.
find_package(Ceres REQUIRED)
add_library(vicc_glyphs_perception_fit
  src/perception/chebyshev_outliers.cpp
  src/perception/level_distribution.cpp
  src/perception/stevens_fit.cpp
  src/perception/survey.cpp
  src/perception/model_fitting.cpp
)
target_compile_options(vicc_glyphs_perception_fit PRIVATE ${VICC_WARNINGS})
target_link_libraries(vicc_glyphs_perception_fit vicc_glyphs_perception Ceres::ceres)

install(TARGETS vicc_glyphs_perception vicc_glyphs_perception_fit
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})
install(DIRECTORY config DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION})

if(CATKIN_ENABLE_TESTING)
  catkin_add_gtest(vicc_glyphs_perception_test
    test/perception/PerceptionModelTest.cpp
    test/perception/PerceptionModelYamlTest.cpp
    test/perception/LevelForValueTest.cpp
  )
  target_compile_options(vicc_glyphs_perception_test PRIVATE ${VICC_WARNINGS})
  target_compile_definitions(vicc_glyphs_perception_test PRIVATE
    VICC_GLYPHS_CONFIG_DIR="${CMAKE_CURRENT_SOURCE_DIR}/config")
  target_link_libraries(vicc_glyphs_perception_test vicc_glyphs_perception gtest_main)

  catkin_add_gtest(vicc_glyphs_perception_fit_test test/perception/ModelFittingTest.cpp)
  target_compile_options(vicc_glyphs_perception_fit_test PRIVATE ${VICC_WARNINGS})
  target_compile_definitions(vicc_glyphs_perception_fit_test PRIVATE
    VICC_GLYPHS_CONFIG_DIR="${CMAKE_CURRENT_SOURCE_DIR}/config")
  target_link_libraries(vicc_glyphs_perception_fit_test vicc_glyphs_perception_fit gtest_main)
endif()
