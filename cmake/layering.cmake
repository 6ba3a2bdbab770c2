# The layers, checked at configure time: libslam (relslam_slam) links Eigen only;
# sim (relslam_sim) adds libslam; only eval (relslam_eval) and what sits on it may reach MRPT,
# OpenCV, JSON and the command line. A library or test program that reaches upward stops the
# configuration here, instead of compiling fine until someone notices.

# Target names above each layer (regular expressions over link-closure target names).
set(RELSLAM_ABOVE_SLAM "^relslam_(sim|eval|mrpt|opencv)$" "^mrpt::" "^opencv_" "^nlohmann_json::" "^CLI11::")
set(RELSLAM_ABOVE_SIM "^relslam_(eval|mrpt|opencv)$" "^mrpt::" "^opencv_" "^nlohmann_json::" "^CLI11::")

# Every target `target` links, directly or through the targets it links, into `out`.
function(relslam_link_closure target out)
  set(seen "")
  set(todo ${target})
  while(todo)
    list(POP_FRONT todo t)
    string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" t "${t}")
    if(NOT TARGET "${t}" OR "${t}" IN_LIST seen)
      continue()
    endif()
    list(APPEND seen "${t}")
    get_target_property(aliased "${t}" ALIASED_TARGET)
    if(aliased)
      list(APPEND todo "${aliased}")
    endif()
    get_target_property(interface "${t}" INTERFACE_LINK_LIBRARIES)
    if(interface)
      list(APPEND todo ${interface})
    endif()
    get_target_property(imported "${t}" IMPORTED)
    get_target_property(type "${t}" TYPE)
    if(NOT imported AND NOT type STREQUAL "INTERFACE_LIBRARY")
      get_target_property(direct "${t}" LINK_LIBRARIES)
      if(direct)
        list(APPEND todo ${direct})
      endif()
    endif()
  endwhile()
  list(REMOVE_ITEM seen "${target}")
  set(${out} "${seen}" PARENT_SCOPE)
endfunction()

# relslam_check_layer(<target> <regex>...): configuration fails if <target> links, directly or
# indirectly, a target whose name matches one of the regexes (e.g. ${RELSLAM_ABOVE_SLAM}).
# Call it after every target involved has been given its links.
function(relslam_check_layer target)
  relslam_link_closure(${target} linked)
  foreach(library IN LISTS linked)
    foreach(pattern IN LISTS ARGN)
      if(library MATCHES "${pattern}")
        message(FATAL_ERROR "${target} links ${library}, which lies above its layer (cmake/layering.cmake)")
      endif()
    endforeach()
  endforeach()
endfunction()
