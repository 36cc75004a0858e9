# PACEMOD (thesis 6.2.3-6.2.4): periodic contour modifications of diffusion curve icons.
# ROS-free: the DCI, the B-spline toolkit, OpenCV (distance transform) and Clipper (isolines).
# Included after cli.cmake, as it adds the `modify` subcommand to vicc_glyph.
if(NOT TARGET vicc_glyphs_bspline)
  message(STATUS "vicc_glyphs: PACEMOD needs the B-spline toolkit; not built")
  return()
endif()

add_library(vicc_glyphs_pacemod
  src/pacemod/wave_spec.cpp
  src/pacemod/wave_layout.cpp
  src/pacemod/feature_transform.cpp
  src/pacemod/nearest_curve_point.cpp
  src/pacemod/skeleton_guard.cpp
  src/pacemod/polyline.cpp
  src/pacemod/polygon_crossings.cpp
  src/pacemod/curve_selection.cpp
  src/pacemod/image_frame.cpp
  src/pacemod/sparse_fowler_bartels.cpp
  src/pacemod/contour_corners.cpp
  src/pacemod/contour_teeth.cpp
  src/pacemod/wave_strips.cpp
  src/pacemod/offset_fit.cpp
  src/pacemod/bend_refit.cpp
  src/pacemod/original_splice.cpp
  src/pacemod/contour_waves.cpp
  src/pacemod/periodic_waves.cpp
  src/pacemod/offset_contour.cpp
  src/pacemod/closed_bezier_fit.cpp
  src/pacemod/dashes.cpp
  src/pacemod/inflate.cpp
)
target_compile_options(vicc_glyphs_pacemod PRIVATE ${VICC_WARNINGS} ${VICC_NO_INTERPOSITION})
target_include_directories(vicc_glyphs_pacemod SYSTEM PUBLIC ${OpenCV_INCLUDE_DIRS})
target_include_directories(vicc_glyphs_pacemod SYSTEM PRIVATE ${VICC_GLYPHS_POLYCLIPPING_INCLUDE_DIRS})
target_link_libraries(vicc_glyphs_pacemod vicc_glyphs_bspline vicc_glyphs_dci ${VICC_GLYPHS_OPENCV}
  ${VICC_GLYPHS_POLYCLIPPING_LIBRARIES})

install(TARGETS vicc_glyphs_pacemod
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})


# The `modify` subcommand of vicc_glyph (registered in src/tools/subcommands.cpp).
if(TARGET vicc_glyph)
  target_sources(vicc_glyph PRIVATE
    src/tools/modify_request.cpp
    src/tools/modify_report.cpp
    src/tools/modify_command.cpp)
  target_link_libraries(vicc_glyph vicc_glyphs_pacemod)
endif()

# The measurements of the PACEMOD bench, shared with its fast GoogleTest subset.
if(TARGET vicc_glyphs_render AND TARGET vicc_glyphs_io)
  add_library(vicc_glyphs_pacemod_measure STATIC
    bench/pacemod/wave_measurement.cpp
    bench/pacemod/wave_check.cpp
    bench/pacemod/contour_overlay.cpp)
  target_compile_options(vicc_glyphs_pacemod_measure PRIVATE ${VICC_WARNINGS})
  target_link_libraries(vicc_glyphs_pacemod_measure vicc_glyphs_pacemod)

  add_executable(vicc_glyphs_pacemod_bench bench/pacemod/pacemod_bench.cpp)
  target_compile_options(vicc_glyphs_pacemod_bench PRIVATE ${VICC_WARNINGS})
  target_include_directories(vicc_glyphs_pacemod_bench PRIVATE bench)
  target_compile_definitions(vicc_glyphs_pacemod_bench PRIVATE
    VICC_GLYPHS_DATA_DIR="${CMAKE_CURRENT_SOURCE_DIR}/data")
  target_link_libraries(vicc_glyphs_pacemod_bench vicc_glyphs_pacemod_measure vicc_glyphs_io vicc_common_cli
    vicc_glyphs_render)
  if(TARGET vicc_glyph_bench_usage_test)  # cli.cmake: the benches' command-line tests
    target_compile_definitions(vicc_glyph_bench_usage_test PRIVATE
      VICC_GLYPHS_PACEMOD_BENCH_BINARY="$<TARGET_FILE:vicc_glyphs_pacemod_bench>")
    add_dependencies(vicc_glyph_bench_usage_test vicc_glyphs_pacemod_bench)
  endif()
endif()

if(CATKIN_ENABLE_TESTING)
  catkin_add_gtest(vicc_glyphs_pacemod_test
    test/pacemod/WaveLayoutTest.cpp
    test/pacemod/FeatureTransformTest.cpp
    test/pacemod/SkeletonGuardTest.cpp
    test/pacemod/ContourWavesTest.cpp
    test/pacemod/ContourCornersTest.cpp
    test/pacemod/SparseFowlerBartelsTest.cpp
    test/pacemod/OriginalSpliceTest.cpp
    test/pacemod/ContourTeethTest.cpp
    test/pacemod/OffsetContourTest.cpp
    test/pacemod/PolylineTest.cpp
    test/pacemod/PolygonCrossingsTest.cpp
    test/pacemod/ImageFrameTest.cpp
  )
  target_compile_options(vicc_glyphs_pacemod_test PRIVATE ${VICC_WARNINGS})
  target_compile_definitions(vicc_glyphs_pacemod_test PRIVATE
    VICC_GLYPHS_DATA_DIR="${CMAKE_CURRENT_SOURCE_DIR}/data")
  target_link_libraries(vicc_glyphs_pacemod_test vicc_glyphs_pacemod gtest_main)
  # Real icons end to end (imports, renders): the fast subset of bench/pacemod.
  if(TARGET vicc_glyphs_pacemod_measure)
    catkin_add_gtest(vicc_glyphs_pacemod_glyph_test test/pacemod/PacemodGlyphTest.cpp
      test/pacemod/CrossingRegressionTest.cpp test/pacemod/WavedGlyphSolveTest.cpp)
    target_compile_options(vicc_glyphs_pacemod_glyph_test PRIVATE ${VICC_WARNINGS})
    target_include_directories(vicc_glyphs_pacemod_glyph_test PRIVATE bench/pacemod)
    target_compile_definitions(vicc_glyphs_pacemod_glyph_test PRIVATE
      VICC_GLYPHS_DATA_DIR="${CMAKE_CURRENT_SOURCE_DIR}/data"
      VICC_GLYPHS_TEST_DATA_DIR="${CMAKE_CURRENT_SOURCE_DIR}/test/data")
    target_link_libraries(vicc_glyphs_pacemod_glyph_test vicc_glyphs_pacemod_measure
      vicc_glyphs_io vicc_glyphs_render vicc_glyphs_render_reference gtest_main)
  endif()
  # vicc_glyph modify as a user runs it.
  if(TARGET vicc_glyph)
    catkin_add_gtest(vicc_glyphs_pacemod_cli_test test/pacemod/ModifyCliTest.cpp)
    target_compile_options(vicc_glyphs_pacemod_cli_test PRIVATE ${VICC_WARNINGS})
    target_compile_definitions(vicc_glyphs_pacemod_cli_test PRIVATE
      VICC_GLYPH_BINARY="$<TARGET_FILE:vicc_glyph>"
      VICC_GLYPHS_DATA_DIR="${CMAKE_CURRENT_SOURCE_DIR}/data")
    target_include_directories(vicc_glyphs_pacemod_cli_test SYSTEM PRIVATE ${OpenCV_INCLUDE_DIRS})
    target_link_libraries(vicc_glyphs_pacemod_cli_test vicc_glyphs_io ${OpenCV_LIBS} gtest_main)
    add_dependencies(vicc_glyphs_pacemod_cli_test vicc_glyph)
  endif()
endif()

# OpenCV labels vs Maurer for the skeleton guard (bench/pacemod/README.md).
if(TARGET vicc_glyphs_io)
  add_executable(vicc_glyphs_feature_transform_bench bench/pacemod/feature_transform_bench.cpp)
  target_compile_options(vicc_glyphs_feature_transform_bench PRIVATE ${VICC_WARNINGS})
  target_include_directories(vicc_glyphs_feature_transform_bench PRIVATE bench)
  target_compile_definitions(vicc_glyphs_feature_transform_bench PRIVATE
    VICC_GLYPHS_DATA_DIR="${CMAKE_CURRENT_SOURCE_DIR}/data")
  target_link_libraries(vicc_glyphs_feature_transform_bench vicc_glyphs_pacemod vicc_glyphs_io
    vicc_common_cli)
endif()
