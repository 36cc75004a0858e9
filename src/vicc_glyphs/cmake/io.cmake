# Formats and icon import (issue 5): Orzan XML, SVG and raster (PNG) to diffusion curves.
find_package(tinyxml2 QUIET)
if(TARGET tinyxml2::tinyxml2)
  set(VICC_GLYPHS_TINYXML2 tinyxml2::tinyxml2)
else()
  set(VICC_GLYPHS_TINYXML2 tinyxml2)
endif()
find_library(VICC_GLYPHS_POTRACE potrace REQUIRED)
find_path(VICC_GLYPHS_POTRACE_INCLUDE potracelib.h REQUIRED)

# vicc_glyphs_formats: Orzan XML and SVG only (no GPL code), for the glyph server and designs.
# vicc_glyphs_io adds raster import (potrace, GPL) and the loader that dispatches to all three.
add_library(vicc_glyphs_formats
  src/io/text_file.cpp
  src/io/xml_attributes.cpp
  src/io/orzan_reader.cpp
  src/io/orzan_writer.cpp
  src/io/usvg_scene_reader.cpp
  src/io/svg_number_scanner.cpp
  src/io/svg_color.cpp
  src/io/svg_transform.cpp
  src/io/svg_geometry.cpp
  src/io/svg_arc.cpp
  src/io/svg_path_data.cpp
  src/io/svg_shapes.cpp
  src/io/svg_style.cpp
  src/io/side_colors.cpp
  src/io/svg_document.cpp
  src/io/svg_import.cpp
)
target_include_directories(vicc_glyphs_formats SYSTEM PRIVATE ${OpenCV_INCLUDE_DIRS})
target_compile_options(vicc_glyphs_formats PRIVATE ${VICC_WARNINGS})
target_link_libraries(vicc_glyphs_formats vicc_glyphs_dci ${VICC_GLYPHS_TINYXML2} ${VICC_GLYPHS_OPENCV})

add_library(vicc_glyphs_io
  src/io/color_quantization.cpp
  src/io/potrace_tracing.cpp
  src/io/raster_import.cpp
  src/io/load.cpp
)
target_include_directories(vicc_glyphs_io SYSTEM PRIVATE ${OpenCV_INCLUDE_DIRS} ${VICC_GLYPHS_POTRACE_INCLUDE})
target_compile_options(vicc_glyphs_io PRIVATE ${VICC_WARNINGS})
target_link_libraries(vicc_glyphs_io vicc_glyphs_formats vicc_glyphs_png ${VICC_GLYPHS_POTRACE}
  ${VICC_GLYPHS_OPENCV})

# The SVG painting model on polygons: Clipper (Debian libpolyclipping-dev, pkg-config polyclipping)
# for boolean operations and stroke offsetting (Boost licence: fine in the formats library).
target_sources(vicc_glyphs_formats PRIVATE
  src/io/clipper_geometry.cpp
  src/io/paint_map.cpp
  src/io/svg_stroke.cpp
  src/io/curve_stroke.cpp
  src/io/svg_css.cpp
  src/io/svg_paint_server.cpp
  src/io/region_curves.cpp
  src/io/svg_viewport.cpp
  src/io/bezier_refit.cpp)
target_include_directories(vicc_glyphs_formats SYSTEM PRIVATE ${VICC_GLYPHS_POLYCLIPPING_INCLUDE_DIRS})
target_link_libraries(vicc_glyphs_formats ${VICC_GLYPHS_POLYCLIPPING_LIBRARIES})

install(TARGETS vicc_glyphs_formats vicc_glyphs_io
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})
install(DIRECTORY data/icons data/samples DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION}/data)

# The stroke outliners' accuracy cases and measurement, shared by their bench and CurveStrokeTest.
add_library(vicc_glyphs_stroke_accuracy STATIC bench/stroke/stroke_accuracy.cpp)
target_include_directories(vicc_glyphs_stroke_accuracy SYSTEM PUBLIC
  ${VICC_GLYPHS_POLYCLIPPING_INCLUDE_DIRS})
target_include_directories(vicc_glyphs_stroke_accuracy PUBLIC src/io bench)
target_compile_options(vicc_glyphs_stroke_accuracy PRIVATE ${VICC_WARNINGS})
target_link_libraries(vicc_glyphs_stroke_accuracy vicc_glyphs_formats)

add_executable(vicc_glyphs_stroke_bench bench/stroke/stroke_outliner_bench.cpp)
target_compile_options(vicc_glyphs_stroke_bench PRIVATE ${VICC_WARNINGS})
target_link_libraries(vicc_glyphs_stroke_bench vicc_glyphs_stroke_accuracy vicc_common_cli)

if(CATKIN_ENABLE_TESTING)
  catkin_add_gtest(vicc_glyphs_io_test
    test/io/OrzanXmlTest.cpp
    test/io/SvgImportTest.cpp
    test/io/SvgPartsTest.cpp
    test/io/RasterImportTest.cpp
    test/io/MalformedInputTest.cpp
    test/io/LoadTest.cpp
    test/io/PublishedSampleTest.cpp
    test/io/UsvgSceneTest.cpp
    test/io/PngCodecTest.cpp
    test/io/CurveStrokeTest.cpp
    test/io/ClipperGeometryTest.cpp
  )
  target_include_directories(vicc_glyphs_io_test SYSTEM PRIVATE ${OpenCV_INCLUDE_DIRS}
    ${VICC_GLYPHS_POLYCLIPPING_INCLUDE_DIRS})
  target_include_directories(vicc_glyphs_io_test PRIVATE src/io)
  target_compile_options(vicc_glyphs_io_test PRIVATE ${VICC_WARNINGS})
  target_compile_definitions(vicc_glyphs_io_test PRIVATE
    VICC_GLYPHS_DATA_DIR="${CMAKE_CURRENT_SOURCE_DIR}/data"
    VICC_GLYPHS_TEST_DATA_DIR="${CMAKE_CURRENT_SOURCE_DIR}/test/data")
  # PublishedSampleTest renders the samples it reads.
  target_link_libraries(vicc_glyphs_io_test vicc_glyphs_io vicc_glyphs_render
    vicc_glyphs_stroke_accuracy ${OpenCV_LIBRARIES} gtest_main)
endif()

if(CATKIN_ENABLE_TESTING)
  # The SVG painting model checked on rendered pixels (needs the renderer).
  catkin_add_gtest(vicc_glyphs_svg_painting_test test/io/SvgPaintingTest.cpp
    test/io/SvgStylePartsTest.cpp)
  target_include_directories(vicc_glyphs_svg_painting_test SYSTEM PRIVATE ${OpenCV_INCLUDE_DIRS}
    ${VICC_GLYPHS_POLYCLIPPING_INCLUDE_DIRS})
  target_include_directories(vicc_glyphs_svg_painting_test PRIVATE src/io)
  target_compile_options(vicc_glyphs_svg_painting_test PRIVATE ${VICC_WARNINGS})
  target_link_libraries(vicc_glyphs_svg_painting_test vicc_glyphs_io vicc_glyphs_render gtest_main)
endif()
