# The vicc_glyph command-line tool and the glyph bench; both need the renderer and the
# importers (io.cmake), so they are skipped while either part is switched off.
if(NOT TARGET vicc_glyphs_render OR NOT TARGET vicc_glyphs_io)
  message(STATUS "vicc_glyphs: vicc_glyph needs the render and io parts; not built")
  return()
endif()

add_executable(vicc_glyph
  src/tools/vicc_glyph_main.cpp
  src/tools/subcommands.cpp
  src/tools/render_command.cpp)
target_compile_options(vicc_glyph PRIVATE ${VICC_WARNINGS})
target_link_libraries(vicc_glyph vicc_glyphs_render vicc_glyphs_io vicc_common_cli)

# Median render time, multigrid cycles and error against the direct solve per input.
add_executable(vicc_glyph_bench bench/glyph_bench.cpp)
target_compile_options(vicc_glyph_bench PRIVATE ${VICC_WARNINGS})
target_include_directories(vicc_glyph_bench PRIVATE test/render bench)
target_link_libraries(vicc_glyph_bench vicc_glyphs_render_reference vicc_glyphs_io vicc_common_cli)
# Per-iteration residual, error estimate and error against the direct solve.
add_executable(vicc_glyph_convergence bench/convergence_history.cpp)
target_compile_options(vicc_glyph_convergence PRIVATE ${VICC_WARNINGS})
target_include_directories(vicc_glyph_convergence PRIVATE test/render)
target_link_libraries(vicc_glyph_convergence vicc_glyphs_render_reference vicc_glyphs_io vicc_common_cli)

install(TARGETS vicc_glyph vicc_glyph_bench
  RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})

if(CATKIN_ENABLE_TESTING)
  catkin_add_gtest(vicc_glyph_cli_test
    test/tools/CliTest.cpp
    test/tools/CommandLineTest.cpp)
  target_compile_options(vicc_glyph_cli_test PRIVATE ${VICC_WARNINGS})
  target_compile_definitions(vicc_glyph_cli_test PRIVATE
    VICC_GLYPH_BINARY="$<TARGET_FILE:vicc_glyph>"
    TEST_DATA_DIR="${CMAKE_CURRENT_SOURCE_DIR}/test/tools")
  target_include_directories(vicc_glyph_cli_test SYSTEM PRIVATE ${OpenCV_INCLUDE_DIRS})
  target_link_libraries(vicc_glyph_cli_test vicc_common_cli ${OpenCV_LIBS} gtest_main)
  add_dependencies(vicc_glyph_cli_test vicc_glyph)

  catkin_add_gtest(vicc_glyph_bench_usage_test test/tools/BenchUsageTest.cpp)
  target_compile_options(vicc_glyph_bench_usage_test PRIVATE ${VICC_WARNINGS})
  target_compile_definitions(vicc_glyph_bench_usage_test PRIVATE
    VICC_GLYPH_BENCH_BINARY="$<TARGET_FILE:vicc_glyph_bench>"
    VICC_GLYPH_CONVERGENCE_BINARY="$<TARGET_FILE:vicc_glyph_convergence>"
    VICC_GLYPHS_STROKE_BENCH_BINARY="$<TARGET_FILE:vicc_glyphs_stroke_bench>"
    VICC_GLYPHS_FEATURE_TRANSFORM_BENCH_BINARY="$<TARGET_FILE:vicc_glyphs_feature_transform_bench>"
    VICC_GLYPHS_DATA_DIR="${CMAKE_CURRENT_SOURCE_DIR}/data")
  # run_command.hpp: the workspace's shared test helpers
  target_include_directories(vicc_glyph_bench_usage_test PRIVATE
    ${CMAKE_CURRENT_SOURCE_DIR}/../../test/common)
  target_link_libraries(vicc_glyph_bench_usage_test gtest_main)
  add_dependencies(vicc_glyph_bench_usage_test vicc_glyph_bench vicc_glyph_convergence
    vicc_glyphs_stroke_bench vicc_glyphs_feature_transform_bench)
endif()
