# gv_git_describe(DIR OUT_VAR): `git describe --tags --always --dirty` of the source tree DIR,
# or "unknown" when DIR is no git checkout (a source tarball) or git is missing.
# As a script it prints the description of GV_DESCRIBE_DIR (tests/integration/version.sh):
#   cmake -DGV_DESCRIBE_DIR=DIR -P cmake/GitDescribe.cmake
function(gv_git_describe dir out)
  set(desc "unknown")
  find_package(Git QUIET)
  if(GIT_FOUND AND EXISTS "${dir}/.git")
    execute_process(COMMAND "${GIT_EXECUTABLE}" -C "${dir}" describe --tags --always --dirty
      OUTPUT_VARIABLE d RESULT_VARIABLE rc OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
    if(rc EQUAL 0 AND NOT d STREQUAL "")
      set(desc "${d}")
    endif()
  endif()
  set(${out} "${desc}" PARENT_SCOPE)
endfunction()

# gv_write_git_describe(DIR FILE): FILE defines GV_GIT_DESCRIBE as DIR's description; the file is
# rewritten only when the description changed, so an unchanged tree recompiles nothing.
function(gv_write_git_describe dir file)
  gv_git_describe("${dir}" d)
  set(text "#define GV_GIT_DESCRIBE \"${d}\"\n")
  if(EXISTS "${file}")
    file(READ "${file}" old)
    if(old STREQUAL text)
      return()
    endif()
  endif()
  file(WRITE "${file}" "${text}")
endfunction()

# Script mode: with GV_DESCRIBE_OUT, refresh that header (the build does it before every compile
# of the library: libgridvector/CMakeLists.txt); without, print the description.
if(CMAKE_SCRIPT_MODE_FILE STREQUAL CMAKE_CURRENT_LIST_FILE)
  if(DEFINED GV_DESCRIBE_OUT)
    gv_write_git_describe("${GV_DESCRIBE_DIR}" "${GV_DESCRIBE_OUT}")
  else()
    gv_git_describe("${GV_DESCRIBE_DIR}" d)
    message("${d}")
  endif()
endif()
