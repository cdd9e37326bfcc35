# pathspace_read_includes(<file> <out>): the #include lines of a source file, for the include checks
# (PathspaceLayerCheck.cmake, PathspaceGpuBenchCheck.cmake). <out> is a list with one element per
# include, "<line number>|<quote>|<path>": the quote is < or ", the path as written.
function(pathspace_read_includes file out)
  set(found "")
  file(READ "${file}" content)
  if(content MATCHES "#[ \t]*include")
    # One list element per line: characters that mean something to CMake lists go first.
    string(REGEX REPLACE "[][;\\\\]" "_" content "${content}")
    string(REPLACE "\n" ";" lines "${content}")
    set(n 0)
    foreach(line IN LISTS lines)
      math(EXPR n "${n} + 1")
      if(line MATCHES "^[ \t]*#[ \t]*include[ \t]*([<\"])([^>\"]*)[>\"]")
        list(APPEND found "${n}|${CMAKE_MATCH_1}|${CMAKE_MATCH_2}")
      endif()
    endforeach()
  endif()
  set(${out} "${found}" PARENT_SCOPE)
endfunction()
