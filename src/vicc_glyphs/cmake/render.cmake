# Multigrid diffusion-curve renderer (ROS-free: Eigen + OpenCV) and its ROS image adapter.

add_library(vicc_glyphs_render
  src/render/lattice_crossings.cpp
  src/render/grid_problem.cpp
  src/render/multigrid_levels.cpp
  src/render/multigrid_deflation.cpp
  src/render/multigrid_local_relaxation.cpp
  src/render/multigrid.cpp
  src/render/constant_regions.cpp
  src/render/curve_antialiasing.cpp
  src/render/variable_blur.cpp
  src/render/renderer.cpp
  src/render/png_output.cpp
  src/render/process_heap.cpp)
target_compile_options(vicc_glyphs_render PRIVATE ${VICC_WARNINGS})
target_include_directories(vicc_glyphs_render SYSTEM PUBLIC ${OpenCV_INCLUDE_DIRS})
target_link_libraries(vicc_glyphs_render vicc_glyphs_dci vicc_glyphs_numerics vicc_glyphs_png ${VICC_GLYPHS_OPENCV})

# sensor_msgs/Image is a header-only message type; only the adapter sees ROS headers.
add_library(vicc_glyphs_ros src/ros/image_message.cpp)
target_compile_options(vicc_glyphs_ros PRIVATE ${VICC_WARNINGS})
target_link_libraries(vicc_glyphs_ros vicc_glyphs_render)
add_dependencies(vicc_glyphs_ros ${catkin_EXPORTED_TARGETS})

install(TARGETS vicc_glyphs_render vicc_glyphs_ros
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})

# The tests' direct sparse solve of a GridProblem, the reference the multigrid is measured
# against, plus their sample images; the bench links it too, so it is not inside the test block.
add_library(vicc_glyphs_render_reference STATIC
  test/render/direct_reference_solve.cpp
  test/render/sample_images.cpp)
target_compile_options(vicc_glyphs_render_reference PRIVATE ${VICC_WARNINGS})
target_link_libraries(vicc_glyphs_render_reference vicc_glyphs_render)

if(CATKIN_ENABLE_TESTING)

  catkin_add_gtest(vicc_glyphs_render_test
    test/render/LatticeCrossingsTest.cpp
    test/render/GridProblemTest.cpp
    test/render/MultigridTest.cpp
    test/render/ConstantRegionsTest.cpp
    test/render/RendererTest.cpp
    test/render/DegenerateInputTest.cpp
    test/render/BarrierConvergenceTest.cpp
    test/render/GalerkinCoarseningTest.cpp
    test/render/DeflationTest.cpp
    test/render/LocalRelaxationTest.cpp
    test/render/CurveAntialiasingTest.cpp
    test/render/ProcessHeapTest.cpp)
  target_compile_options(vicc_glyphs_render_test PRIVATE ${VICC_WARNINGS})
  # GalerkinCoarseningTest checks the solver's internal operators.
  target_include_directories(vicc_glyphs_render_test PRIVATE src/render)
  # BarrierConvergenceTest reads a vendored sample.
  target_compile_definitions(vicc_glyphs_render_test PRIVATE
    VICC_GLYPHS_DATA_DIR="${CMAKE_CURRENT_SOURCE_DIR}/data")
  target_link_libraries(vicc_glyphs_render_test vicc_glyphs_render_reference vicc_glyphs_io
    gtest_main)

  catkin_add_gtest(vicc_glyphs_ros_test test/render/ImageMessageTest.cpp)
  target_compile_options(vicc_glyphs_ros_test PRIVATE ${VICC_WARNINGS})
  target_link_libraries(vicc_glyphs_ros_test vicc_glyphs_ros gtest_main)
endif()

# Fidelity benchmark helper (bench/fidelity/run_fidelity.sh): dark-mask IoU and gray difference
# between a vicc_glyph render and rsvg-convert's.
add_executable(vicc_glyph_fidelity_compare bench/fidelity/compare_masks.cpp)
target_compile_options(vicc_glyph_fidelity_compare PRIVATE ${VICC_WARNINGS})
target_include_directories(vicc_glyph_fidelity_compare SYSTEM PRIVATE ${OpenCV_INCLUDE_DIRS})
target_link_libraries(vicc_glyph_fidelity_compare ${OpenCV_LIBS})
