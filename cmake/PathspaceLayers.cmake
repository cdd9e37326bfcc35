# The layers of src/pathspace/ (docs/architecture.md §2), defined once. Used by
# src/pathspace/CMakeLists.txt (one CMake target pathspace_<layer> per layer, linking the layers in
# its _BELOW list) and by cmake/PathspaceLayerCheck.cmake (the include check run in every build and
# by the `layers.*` tests), so the targets and the include rule cannot drift apart.
#
#   PATHSPACE_LAYERS                  the layers, lowest first
#   PATHSPACE_LAYER_<layer>_FOLDERS   folders of src/pathspace/ in the layer, in order: a folder may
#                                     include itself and the folders listed before it, never after
#   PATHSPACE_LAYER_<layer>_BELOW     the layers it links (and includes) directly; what it may include
#                                     is these, transitively (pathspace_layer_allowed)
#   PATHSPACE_TOP_FOLDERS             folders of src/pathspace/ that are consumers, not a layer (they
#                                     may include anything and are not part of any library target)
#
# Adding a folder to src/pathspace/ means adding it here; the check fails on a folder found nowhere.
# This file must stay usable in script mode (cmake -P): no targets, no project() variables.

set(PATHSPACE_LAYERS base geometry scene accel io integrators session checkpoint study)

set(PATHSPACE_LAYER_base_FOLDERS        base math parallel options stats)
set(PATHSPACE_LAYER_base_BELOW          "")
set(PATHSPACE_LAYER_geometry_FOLDERS    sampling geometry camera hashgrid)
set(PATHSPACE_LAYER_geometry_BELOW      base)
set(PATHSPACE_LAYER_scene_FOLDERS       media materials lights scene film)
set(PATHSPACE_LAYER_scene_BELOW         geometry)
set(PATHSPACE_LAYER_accel_FOLDERS       accel)
set(PATHSPACE_LAYER_accel_BELOW         scene)
# io is a sibling of accel, integrators and session: neither side includes the other.
set(PATHSPACE_LAYER_io_FOLDERS          io)
set(PATHSPACE_LAYER_io_BELOW            scene)
set(PATHSPACE_LAYER_integrators_FOLDERS filters integrators gpu)
set(PATHSPACE_LAYER_integrators_BELOW   accel)
set(PATHSPACE_LAYER_session_FOLDERS     session)
set(PATHSPACE_LAYER_session_BELOW       integrators)
# checkpoint: a session's state in a file (session's state, io's atomic writes).
set(PATHSPACE_LAYER_checkpoint_FOLDERS  checkpoint)
set(PATHSPACE_LAYER_checkpoint_BELOW    session io)
set(PATHSPACE_LAYER_study_FOLDERS       study)
set(PATHSPACE_LAYER_study_BELOW         session io)

# cuda/: the nvcc compile check of the kernel headers, a test-like consumer.
set(PATHSPACE_TOP_FOLDERS cuda)

# pathspace_layer_of_folder(<folder> <out_layer>): the layer of a folder, "top" for a top folder,
# "" when the folder is in no layer.
function(pathspace_layer_of_folder folder out_layer)
  set(result "")
  foreach(layer IN LISTS PATHSPACE_LAYERS)
    if(folder IN_LIST PATHSPACE_LAYER_${layer}_FOLDERS)
      set(result ${layer})
      break()
    endif()
  endforeach()
  if(result STREQUAL "" AND folder IN_LIST PATHSPACE_TOP_FOLDERS)
    set(result top)
  endif()
  set(${out_layer} "${result}" PARENT_SCOPE)
endfunction()

# pathspace_layer_allowed(<layer> <out_list>): the layers below <layer> that it may include (the
# transitive closure of _BELOW), not <layer> itself.
function(pathspace_layer_allowed layer out_list)
  set(result "")
  set(todo ${PATHSPACE_LAYER_${layer}_BELOW})
  while(todo)
    list(POP_FRONT todo next)
    if(NOT next IN_LIST result)
      list(APPEND result ${next})
      list(APPEND todo ${PATHSPACE_LAYER_${next}_BELOW})
    endif()
  endwhile()
  set(${out_list} "${result}" PARENT_SCOPE)
endfunction()

# pathspace_may_include(<folder A> <folder B> <out_bool>): whether a file in folder A may include a
# header of folder B. Both folders must be in a layer (or A a top folder).
function(pathspace_may_include from to out_bool)
  pathspace_layer_of_folder(${from} from_layer)
  pathspace_layer_of_folder(${to} to_layer)
  set(ok FALSE)
  if(from_layer STREQUAL "top" OR from STREQUAL to)
    set(ok TRUE)
  elseif(from_layer STREQUAL to_layer)
    list(FIND PATHSPACE_LAYER_${from_layer}_FOLDERS ${from} i_from)
    list(FIND PATHSPACE_LAYER_${to_layer}_FOLDERS ${to} i_to)
    if(i_to LESS i_from)
      set(ok TRUE)
    endif()
  else()
    pathspace_layer_allowed(${from_layer} allowed)
    if(to_layer IN_LIST allowed)
      set(ok TRUE)
    endif()
  endif()
  set(${out_bool} ${ok} PARENT_SCOPE)
endfunction()
