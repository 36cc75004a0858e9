# The build's install rules run into a temporary prefix; the installed CLIs, node and nodelet
# are started from there with the checkout hidden (test/InstallSpaceTest.cpp). What this build
# does not have (CATKIN_WHITELIST_PACKAGES) is left out: the checks are switched on at generate
# time by whether the tool's target exists ($<TARGET_EXISTS>, whatever the configure order).
catkin_add_gtest(vicc_install_space_test test/InstallSpaceTest.cpp)
# run_command.hpp: the workspace's shared test helpers
target_include_directories(vicc_install_space_test PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/../../test/common)
target_compile_options(vicc_install_space_test PRIVATE ${VICC_WARNINGS})
target_compile_definitions(vicc_install_space_test PRIVATE
  VICC_SOURCE_DIR="${CMAKE_SOURCE_DIR}" VICC_BUILD_DIR="${CMAKE_BINARY_DIR}"
  VICC_DEVEL_DIR="${CATKIN_DEVEL_PREFIX}" VICC_INSTALL_PREFIX="${CMAKE_INSTALL_PREFIX}"
  $<$<AND:$<TARGET_EXISTS:tracker>,$<TARGET_EXISTS:vicc_tracking_nodelets>,$<TARGET_EXISTS:vicc_make_bag>>:VICC_HAS_TRACKING>
  $<$<TARGET_EXISTS:vicc_patient>:VICC_HAS_ANATOMY>
  $<$<TARGET_EXISTS:vicc_glyph>:VICC_HAS_GLYPHS>)
target_link_libraries(vicc_install_space_test gtest_main)
