# cmake -DBINARY= -DSOURCE_DIR= -DBUILD_DIR= -DOUT_DIR= -DNAME= -P make_tarball.cmake
# OUT_DIR/NAME.tar.gz: the static essi (stripped), its man page and shell completions, the examples, README,
# LICENSE, THIRD-PARTY-NOTICES and CHANGELOG, in one folder NAME/ (docs/install.md).
set(stage ${BUILD_DIR}/tarball/${NAME})
file(REMOVE_RECURSE ${BUILD_DIR}/tarball)
file(MAKE_DIRECTORY ${stage}/share/man/man1 ${stage}/share/completions ${stage}/examples ${OUT_DIR})
file(COPY_FILE ${BINARY} ${stage}/essi)
execute_process(COMMAND strip ${stage}/essi RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "strip ${stage}/essi failed")
endif()
file(COPY ${BUILD_DIR}/share/man/man1/essi.1 DESTINATION ${stage}/share/man/man1)
file(COPY ${BUILD_DIR}/share/completions/essi.bash ${BUILD_DIR}/share/completions/_essi
          ${BUILD_DIR}/share/completions/essi.fish DESTINATION ${stage}/share/completions)
file(GLOB examples ${SOURCE_DIR}/examples/*.esi ${SOURCE_DIR}/examples/*.eia)
file(COPY ${examples} DESTINATION ${stage}/examples)
file(COPY ${SOURCE_DIR}/README.md ${SOURCE_DIR}/LICENSE ${SOURCE_DIR}/THIRD-PARTY-NOTICES.md ${SOURCE_DIR}/CHANGELOG.md
     DESTINATION ${stage})
# Reproducible: sorted names, one owner, the time of the last commit (SOURCE_DATE_EPOCH) or 0.
if(DEFINED ENV{SOURCE_DATE_EPOCH})
  set(mtime "@$ENV{SOURCE_DATE_EPOCH}")
else()
  set(mtime "@0")
endif()
execute_process(
  COMMAND tar --sort=name --owner=0 --group=0 --numeric-owner --mtime=${mtime} -czf ${OUT_DIR}/${NAME}.tar.gz ${NAME}
  WORKING_DIRECTORY ${BUILD_DIR}/tarball
  RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "tar ${OUT_DIR}/${NAME}.tar.gz failed")
endif()
message(STATUS "${OUT_DIR}/${NAME}.tar.gz")
