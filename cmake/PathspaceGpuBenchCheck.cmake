# The standalone GPU filter benchmark's include check: cmake -DROOT=<repository> -P this file.
#
# bench/cuda/CMakeLists.txt builds on the lent GPU machine, which has the CUDA toolkit and CMake but
# no Debian -dev packages (docs/gpu.md). Every file it compiles, and every pathspace header those
# include directly or not, must therefore include no third-party package (oneTBB, fmt, nlohmann-json,
# OpenEXR, ...). A build with those packages installed does not notice such an include, and one that
# only links (oneTBB's parallel_for) fails only where nvcc is found: CI's link of the benchmark once
# did. This check runs in every build, with or without CUDA, and reports `file:line: message` with
# the chain of includes that reached the file. Fails (exit status 1) when it reports anything.
cmake_minimum_required(VERSION 3.25)

if(NOT DEFINED ROOT)
  message(FATAL_ERROR "usage: cmake -DROOT=<repository root> -P ${CMAKE_CURRENT_LIST_FILE}")
endif()
get_filename_component(ROOT "${ROOT}" ABSOLUTE)
set(bench_list "${ROOT}/bench/cuda/CMakeLists.txt")
if(NOT EXISTS "${bench_list}")
  return()
endif()

# The packages of docs/toolchain.md that a header names by its own folder or file.
set(third_party_regex "^(tbb|oneapi|fmt|nlohmann|OpenEXR|Imath|CLI|embree[0-9]*|pugixml|tiny_obj_loader|tiny_gltf|stb_|zlib|gtest|gmock|benchmark|pybind11|mpi)[/._]")
include(${CMAKE_CURRENT_LIST_DIR}/PathspaceIncludeLines.cmake)

# The sources: the benchmark's own .cu files and each ${src}/... path its list names.
file(GLOB pending "${ROOT}/bench/cuda/*.cu")
file(READ "${bench_list}" bench_text)
string(REGEX MATCHALL "\\$\\{src\\}/[^ \t\r\n)]+" named "${bench_text}")
foreach(path IN LISTS named)
  string(REPLACE "\${src}/" "${ROOT}/src/pathspace/" path "${path}")
  list(APPEND pending "${path}")
endforeach()

set(errors "")
set(visited "")
# Which file first included each header (parallel lists: header i was reached from parent i).
set(reached "")
set(reached_parent "")
while(pending)
  list(POP_FRONT pending file)
  if(file IN_LIST visited)
    continue()
  endif()
  list(APPEND visited "${file}")
  if(NOT EXISTS "${file}")
    list(APPEND errors "${bench_list}:1: compiles ${file}, which does not exist")
    continue()
  endif()
  pathspace_read_includes("${file}" includes)
  foreach(include IN LISTS includes)
    string(REGEX MATCH "^([0-9]+)\\|.\\|(.*)$" _ "${include}")
    set(n "${CMAKE_MATCH_1}")
    set(path "${CMAKE_MATCH_2}")
    if(path MATCHES "^pathspace/")
      set(header "${ROOT}/src/${path}")
      if(NOT header IN_LIST visited AND NOT header IN_LIST reached)
        list(APPEND pending "${header}")
        list(APPEND reached "${header}")
        list(APPEND reached_parent "${file}")
      endif()
    elseif(path MATCHES "${third_party_regex}")
      set(chain "")
      set(at "${file}")
      list(FIND reached "${at}" i)
      while(i GREATER_EQUAL 0)
        list(GET reached_parent ${i} at)
        string(APPEND chain " <- ${at}")
        list(FIND reached "${at}" i)
      endwhile()
      list(APPEND errors "${file}:${n}: includes ${path}, which the GPU machine lacks (bench/cuda reaches this file${chain})")
    endif()
  endforeach()
endwhile()

list(LENGTH errors n_errors)
if(n_errors GREATER 0)
  foreach(e IN LISTS errors)
    message("${e}")
  endforeach()
  message(FATAL_ERROR "GPU benchmark check: ${n_errors} problem(s). Move the code that needs the package into a file "
                      "bench/cuda/CMakeLists.txt does not compile (e.g. filters/vertex_buffer_copy.cpp).")
endif()
list(LENGTH visited files_checked)
message(STATUS "GPU benchmark check: ${files_checked} files, no third-party include")
