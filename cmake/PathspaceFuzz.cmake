# PATHSPACE_FUZZ: libFuzzer targets for the scene parsers (tests/fuzz/, docs/fuzzing.md).
# Needs clang (CMAKE_CXX_COMPILER=clang++) and its libFuzzer runtime (Debian: libclang-rt-14-dev;
# scripts/install-deps --fuzz). Everything in the build is compiled with coverage instrumentation
# and ASan/UBSan, so the parsers under test report memory errors and undefined behaviour at once.
option(PATHSPACE_FUZZ "Build the libFuzzer targets of the scene parsers (clang only)" OFF)
if(PATHSPACE_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "PATHSPACE_FUZZ needs clang: configure with -DCMAKE_CXX_COMPILER=clang++")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -g)
  add_link_options(-fsanitize=address,undefined)
endif()
