# The git revision goes into every manifest.json. It is read at build time (not only at
# configure time), so a commit followed by `cmake --build` never records a stale revision.
set(RELSLAM_GIT_REVISION_FILE ${CMAKE_BINARY_DIR}/generated/git_revision.cpp)
add_custom_target(relslam_git_revision
  COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${CMAKE_SOURCE_DIR} -DOUTPUT=${RELSLAM_GIT_REVISION_FILE}
          -P ${CMAKE_SOURCE_DIR}/cmake/write_git_revision.cmake
  BYPRODUCTS ${RELSLAM_GIT_REVISION_FILE}
  COMMENT "Reading git revision")
