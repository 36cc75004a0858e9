# vicc_link_devel_share(DIR...): makes <devel>/share/<project>/DIR a symbolic link to the
# package's source DIR, so that the devel space has the same share/<package>/ layout as the
# install space (where install(DIRECTORY DIR ...) puts the files). vicc_paths then finds a
# package's data the same way in both, with no source path compiled into any binary.
function(vicc_link_devel_share)
  set(share_dir ${CATKIN_DEVEL_PREFIX}/share/${PROJECT_NAME})
  file(MAKE_DIRECTORY ${share_dir})
  foreach(dir ${ARGN})
    if(NOT IS_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/${dir})
      message(FATAL_ERROR "vicc_link_devel_share: ${PROJECT_NAME} has no directory '${dir}'")
    endif()
    file(CREATE_LINK ${CMAKE_CURRENT_SOURCE_DIR}/${dir} ${share_dir}/${dir} SYMBOLIC)
  endforeach()
endfunction()
