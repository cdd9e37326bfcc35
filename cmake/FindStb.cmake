# FindStb: the stb single-file headers (stb_image.h, stb_image_write.h; Debian 12: libstb-dev), as
# the header-only imported target Stb::stb. pathspace compiles the implementations it needs itself
# (io/image_io.cpp), so only the include directory is used, not the libstb that stb.pc names.
# Looks in the include directories of pkg-config's stb.pc when there is one, then in the usual
# prefixes (<prefix>/include/stb); -DStb_INCLUDE_DIR=<dir> overrides.
find_package(PkgConfig QUIET)
if(PKG_CONFIG_FOUND)
  pkg_check_modules(PC_STB QUIET stb)
endif()
find_path(Stb_INCLUDE_DIR NAMES stb_image.h HINTS ${PC_STB_INCLUDE_DIRS} PATH_SUFFIXES stb
          DOC "Directory of stb_image.h and stb_image_write.h")
if(Stb_INCLUDE_DIR AND NOT EXISTS "${Stb_INCLUDE_DIR}/stb_image_write.h")
  set(Stb_INCLUDE_DIR "Stb_INCLUDE_DIR-NOTFOUND" CACHE PATH "Directory of stb_image.h and stb_image_write.h" FORCE)
endif()
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(Stb
  REQUIRED_VARS Stb_INCLUDE_DIR
  REASON_FAILURE_MESSAGE "stb_image.h and stb_image_write.h not found: install libstb-dev (scripts/install-deps) or pass -DStb_INCLUDE_DIR=<dir>")
if(Stb_FOUND AND NOT TARGET Stb::stb)
  add_library(Stb::stb INTERFACE IMPORTED)
  set_target_properties(Stb::stb PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${Stb_INCLUDE_DIR}")
endif()
mark_as_advanced(Stb_INCLUDE_DIR)
