# Which scene formats this build can fuzz and replay: the Mitsuba loader only when pathspace_io
# compiles it. Sets PATHSPACE_HAS_MITSUBA (0/1) and PATHSPACE_FUZZ_FORMATS.
get_target_property(_pathspace_io_sources pathspace_io SOURCES)
list(FILTER _pathspace_io_sources INCLUDE REGEX "mitsuba_loader\\.cpp$")
if(_pathspace_io_sources)
  set(PATHSPACE_HAS_MITSUBA 1)
  set(PATHSPACE_FUZZ_FORMATS pbrt ply obj mitsuba gltf image)
else()
  set(PATHSPACE_HAS_MITSUBA 0)
  set(PATHSPACE_FUZZ_FORMATS pbrt ply obj gltf image)
endif()
