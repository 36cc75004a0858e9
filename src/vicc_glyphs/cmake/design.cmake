# Glyph designs as data (thesis 6.2.5): design files, data levels, building the modified icon
# with PACEMOD. Links the SVG/XML formats only (no raster import, no GPL code), so the glyph
# server can use it. Adds the `design` subcommand to vicc_glyph.
if(NOT TARGET vicc_glyphs_pacemod OR NOT TARGET vicc_glyphs_perception)
  message(STATUS "vicc_glyphs: designs need PACEMOD and the perception model; not built")
  return()
endif()

add_library(vicc_glyphs_design
  src/design/design_yaml.cpp
  src/design/glyph_design.cpp
  src/design/design_values.cpp
  src/design/gradient_channels.cpp
  src/design/design_builder.cpp
  src/design/design_check.cpp
  src/design/background_check.cpp
)
target_compile_options(vicc_glyphs_design PRIVATE ${VICC_WARNINGS})
find_package(Threads REQUIRED)
target_link_libraries(vicc_glyphs_design vicc_glyphs_pacemod vicc_glyphs_perception
  vicc_glyphs_formats yaml-cpp Threads::Threads)

install(TARGETS vicc_glyphs_design
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})
install(DIRECTORY designs DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION})

if(TARGET vicc_glyph)
  target_sources(vicc_glyph PRIVATE src/tools/design_command.cpp src/tools/design_map_command.cpp
    src/tools/check_design_command.cpp)
  target_link_libraries(vicc_glyph vicc_glyphs_design)
endif()

# The designs' build and render times (bench/design/design_bench.cpp; not run by make test).
if(TARGET vicc_glyph)
  add_executable(vicc_glyphs_design_bench bench/design/design_bench.cpp)
  target_compile_options(vicc_glyphs_design_bench PRIVATE ${VICC_WARNINGS})
  target_include_directories(vicc_glyphs_design_bench PRIVATE bench)
  target_compile_definitions(vicc_glyphs_design_bench PRIVATE
    VICC_GLYPHS_CONFIG_DIR="${CMAKE_CURRENT_SOURCE_DIR}/config"
    VICC_GLYPHS_DESIGNS_DIR="${CMAKE_CURRENT_SOURCE_DIR}/designs")
  target_link_libraries(vicc_glyphs_design_bench vicc_glyphs_design vicc_glyphs_pacemod vicc_glyphs_render
    vicc_common_cli)
  if(TARGET vicc_glyph_bench_usage_test)  # cli.cmake: the benches' command-line tests
    target_compile_definitions(vicc_glyph_bench_usage_test PRIVATE
      VICC_GLYPHS_DESIGN_BENCH_BINARY="$<TARGET_FILE:vicc_glyphs_design_bench>"
      VICC_GLYPHS_DESIGNS_DIR="${CMAKE_CURRENT_SOURCE_DIR}/designs")
    add_dependencies(vicc_glyph_bench_usage_test vicc_glyphs_design_bench)
  endif()
endif()

if(CATKIN_ENABLE_TESTING)
  catkin_add_gtest(vicc_glyphs_design_test
    test/design/GlyphDesignTest.cpp
    test/design/DesignBuildTest.cpp
    test/design/IcpColourTest.cpp
    test/design/BackgroundCheckTest.cpp)
  target_compile_options(vicc_glyphs_design_test PRIVATE ${VICC_WARNINGS})
  target_compile_definitions(vicc_glyphs_design_test PRIVATE
    VICC_GLYPHS_CONFIG_DIR="${CMAKE_CURRENT_SOURCE_DIR}/config"
    VICC_GLYPHS_DESIGNS_DIR="${CMAKE_CURRENT_SOURCE_DIR}/designs")
  target_link_libraries(vicc_glyphs_design_test vicc_glyphs_design vicc_glyphs_render gtest_main)

  if(TARGET vicc_glyph)
    catkin_add_gtest(vicc_glyph_design_cli_test test/design/DesignCliTest.cpp)
    target_compile_options(vicc_glyph_design_cli_test PRIVATE ${VICC_WARNINGS})
    target_compile_definitions(vicc_glyph_design_cli_test PRIVATE
      VICC_GLYPH_BINARY="$<TARGET_FILE:vicc_glyph>"
      VICC_GLYPHS_DESIGNS_DIR="${CMAKE_CURRENT_SOURCE_DIR}/designs")
    target_include_directories(vicc_glyph_design_cli_test SYSTEM PRIVATE ${OpenCV_INCLUDE_DIRS})
    target_link_libraries(vicc_glyph_design_cli_test ${OpenCV_LIBS} gtest_main)
    add_dependencies(vicc_glyph_design_cli_test vicc_glyph)
  endif()
endif()
