# B-spline toolkit (thesis 2.5, 6.2.3.2-6.2.3.4): evaluation, knot insertion, Frenet frame,
# Bezier <-> B-spline conversion, arc length, least squares, ELSPIA and Fowler-Bartels.
# Eigen only, no ROS.
add_library(vicc_glyphs_bspline
  src/bspline/bspline_curve.cpp
  src/bspline/knot_insertion.cpp
  src/bspline/frenet_frame.cpp
  src/bspline/chain_parameter_map.cpp
  src/bspline/bezier_conversion.cpp
  src/bspline/spline_diffusion_curve.cpp
  src/bspline/arc_length.cpp
  src/bspline/fitting.cpp
  src/bspline/curve_energy.cpp
  src/bspline/elspia.cpp
  src/bspline/fowler_bartels.cpp
)
target_compile_options(vicc_glyphs_bspline PRIVATE ${VICC_WARNINGS} ${VICC_NO_INTERPOSITION})
target_link_libraries(vicc_glyphs_bspline vicc_glyphs_dci vicc_glyphs_numerics)

install(TARGETS vicc_glyphs_bspline
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})

if(CATKIN_ENABLE_TESTING)
  catkin_add_gtest(vicc_glyphs_bspline_test
    test/bspline/BSplineCurveTest.cpp
    test/bspline/KnotInsertionTest.cpp
    test/bspline/FrenetFrameTest.cpp
    test/bspline/BezierConversionTest.cpp
    test/bspline/ArcLengthTest.cpp
    test/bspline/FittingTest.cpp
    test/bspline/ElspiaTest.cpp
    test/bspline/FowlerBartelsTest.cpp
    test/numerics/BandedCholeskyTest.cpp
  )
  target_compile_options(vicc_glyphs_bspline_test PRIVATE ${VICC_WARNINGS})
  target_link_libraries(vicc_glyphs_bspline_test vicc_glyphs_bspline gtest_main)
endif()
