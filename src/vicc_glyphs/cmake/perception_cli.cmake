# The perception model's vicc_glyph subcommands (levels, fit-model); added to the tool that
# cli.cmake defines, so that fragment stays untouched.
if(NOT TARGET vicc_glyph OR NOT TARGET vicc_glyphs_perception)
  return()
endif()

target_sources(vicc_glyph PRIVATE
  src/tools/model_path.cpp
  src/tools/levels_command.cpp
  src/tools/fit_command.cpp)
# The default model: share/vicc_glyphs/config (vicc_paths), in devel and install.
target_link_libraries(vicc_glyph vicc_glyphs_perception_fit vicc_paths)

if(CATKIN_ENABLE_TESTING)
  catkin_add_gtest(vicc_glyph_perception_cli_test
    test/perception/LevelsCliTest.cpp
    test/perception/FitModelCliTest.cpp)
  target_compile_options(vicc_glyph_perception_cli_test PRIVATE ${VICC_WARNINGS})
  target_compile_definitions(vicc_glyph_perception_cli_test PRIVATE
    VICC_GLYPH_BINARY="$<TARGET_FILE:vicc_glyph>"
    VICC_GLYPHS_CONFIG_DIR="${CMAKE_CURRENT_SOURCE_DIR}/config")
  target_link_libraries(vicc_glyph_perception_cli_test vicc_glyphs_perception_fit gtest_main)
  add_dependencies(vicc_glyph_perception_cli_test vicc_glyph)
endif()
