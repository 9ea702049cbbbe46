# The sub-folders of a layer and which of their siblings each may include (docs/architecture.md).
# A layer's files build into one target, so the layer guards (layers.cmake) cannot tell its
# sub-folders apart: this check reads their includes when CMake configures, and stops it with
# the file, the include and the rule. As a script (cmake -DSWEEP_ROOT=DIR -P this file) it checks
# the tree under DIR; tests/CMakeLists.txt runs it so on a tree that breaks a rule.
#
# "layer/folder:sibling,sibling": the siblings folder may include; a folder not listed here may
# include every sibling (a new sub-folder starts without rules until it is given one).
cmake_policy(SET CMP0057 NEW)  # if(... IN_LIST ...), also when run as a script
set(SWEEP_SUBFOLDER_RULES
    "geometry/mesh:"
    "geometry/curves:"
    "geometry/subdivision:mesh"
    "geometry/surfaces:curves,mesh,subdivision"
    "model/kinds:"
    "model/evaluation:kinds"
    "model/edit:kinds,evaluation"
    "model/print:kinds,evaluation"
    "io/files:"
    "io/swp:files"
    "io/svg:files,mesh"
    "io/mesh:files")

function(sweep_check_subfolders root)
  foreach(rule ${SWEEP_SUBFOLDER_RULES})
    string(REGEX MATCH "^([a-z_]+)/([a-z_]+):(.*)$" matched "${rule}")
    set(layer ${CMAKE_MATCH_1})
    set(folder ${CMAKE_MATCH_2})
    string(REPLACE "," ";" allowed "${CMAKE_MATCH_3}")
    file(GLOB_RECURSE files ${root}/src/${layer}/${folder}/*.hpp ${root}/src/${layer}/${folder}/*.cpp)
    foreach(file ${files})
      file(STRINGS ${file} includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"${layer}/[a-z_]+/")
      foreach(line ${includes})
        string(REGEX MATCH "\"${layer}/([a-z_]+)/" sibling "${line}")
        set(sibling ${CMAKE_MATCH_1})
        if(NOT sibling STREQUAL folder AND NOT sibling IN_LIST allowed)
          file(RELATIVE_PATH shown ${root} ${file})
          string(REPLACE ";" ", " may "${allowed}")
          if(may STREQUAL "")
            set(may "none of its siblings")
          endif()
          message(FATAL_ERROR "${shown}: ${line}: src/${layer}/${folder}/ may include ${may} "
                              "(cmake/subfolders.cmake, docs/architecture.md)")
        endif()
      endforeach()
    endforeach()
  endforeach()
endfunction()

# The viewer's panels that are handed only their parts of its state (panels/panel_parts.hpp):
# they may include the panels' own headers and the parts (app/viewer/state/, selected_curve.hpp),
# never a header of the viewer's whole state (viewer_state.hpp, actions.hpp, ...).
set(SWEEP_PART_PANELS
    objects_panel stats_panel error_panel status_bar help_window create_panel material_panel edit_panel
    point_table curve_tools surface_fields rider_fields number_field panel_support)
set(SWEEP_PART_HEADERS selected_curve item_positions)

function(sweep_check_panel_parts root)
  foreach(panel ${SWEEP_PART_PANELS})
    foreach(file ${root}/src/app/viewer/panels/${panel}.cpp ${root}/src/app/viewer/panels/${panel}.hpp)
      if(NOT EXISTS ${file})
        continue()
      endif()
      file(STRINGS ${file} includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"app/viewer/[a-z_]+\\.hpp\"")
      foreach(line ${includes})
        string(REGEX MATCH "\"app/viewer/([a-z_]+)\\.hpp\"" header "${line}")
        if(NOT CMAKE_MATCH_1 IN_LIST SWEEP_PART_HEADERS)
          file(RELATIVE_PATH shown ${root} ${file})
          message(FATAL_ERROR "${shown}: ${line}: this panel is handed only its parts of the viewer's state "
                              "(panels/panel_parts.hpp, cmake/subfolders.cmake, docs/architecture.md)")
        endif()
      endforeach()
    endforeach()
  endforeach()
endfunction()

# A folder's detail/ headers are its layer's own (src/io/swp/detail/lexer.hpp is the SWP reader's):
# no file of src/ outside that layer includes one.
function(sweep_check_details root)
  file(GLOB_RECURSE files ${root}/src/*.hpp ${root}/src/*.cpp)
  foreach(file ${files})
    file(STRINGS ${file} includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"[a-z_]+/([a-z_]+/)*detail/")
    foreach(line ${includes})
      string(REGEX MATCH "\"([a-z_]+)/" layer "${line}")
      set(layer ${CMAKE_MATCH_1})
      file(RELATIVE_PATH shown ${root} ${file})
      if(NOT shown MATCHES "^src/${layer}/")
        message(FATAL_ERROR "${shown}: ${line}: a detail/ header is for src/${layer}/ alone; include the folder's "
                            "public header (its README says which) (cmake/subfolders.cmake, docs/architecture.md)")
      endif()
    endforeach()
  endforeach()
endfunction()

if(CMAKE_SCRIPT_MODE_FILE STREQUAL CMAKE_CURRENT_LIST_FILE)
  get_filename_component(root "${SWEEP_ROOT}" ABSOLUTE)
  sweep_check_subfolders(${root})
  sweep_check_panel_parts(${root})
  sweep_check_details(${root})
endif()
