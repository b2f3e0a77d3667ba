# essi_version_header(OUT_DIR): OUT_DIR/essi_version.hpp from native/version.hpp.in, with CMake's project(VERSION)
# and the git commit of the sources (`essi --version`, SARIF, JUnit, /api/health). A commit re-configures the build
# (the files git moves on a commit are configure dependencies of the calling folder), so the commit is current.
# Used by native/ (the CLI) and npm/ (the same CLI built for node).
function(essi_version_header out_dir)
  set(ESSIKIT_GIT_COMMIT "unknown")
  find_package(Git QUIET)
  if(GIT_FOUND AND EXISTS ${CMAKE_SOURCE_DIR}/.git)
    execute_process(COMMAND ${GIT_EXECUTABLE} -C ${CMAKE_SOURCE_DIR} rev-parse --short=12 HEAD
                    OUTPUT_VARIABLE _commit OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE _git_rc)
    if(_git_rc EQUAL 0 AND _commit MATCHES "^[0-9a-f]+$")
      set(ESSIKIT_GIT_COMMIT "${_commit}")
    endif()
    # (.git is a file in a worktree: the commit is then still found, only the configure dependencies are not)
    foreach(_git_file HEAD packed-refs)
      if(EXISTS ${CMAKE_SOURCE_DIR}/.git/${_git_file})
        set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/.git/${_git_file})
      endif()
    endforeach()
    execute_process(COMMAND ${GIT_EXECUTABLE} -C ${CMAKE_SOURCE_DIR} symbolic-ref -q HEAD
                    OUTPUT_VARIABLE _ref OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
    if(_ref AND EXISTS ${CMAKE_SOURCE_DIR}/.git/${_ref})
      set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/.git/${_ref})
    endif()
  endif()
  configure_file(${CMAKE_SOURCE_DIR}/native/version.hpp.in ${out_dir}/essi_version.hpp @ONLY)
endfunction()
