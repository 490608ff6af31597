# Checks the layer table of cmake/SubdivLayers.cmake against the code:
#  1. every #include "framework/<layer>/..." in framework/<layer'>/ names a layer that
#     <layer'> may use (or its own);
#  2. inside a layer with rooms (analysis/curve, analysis/surface), a room includes only the
#     rooms before it;
#  3. framework/io/vtk (library subdiv_vtkio) uses only its own layers;
#  4. no VTK header is included outside framework/io/vtk (libsubdiv is VTK-free);
#  5. an installed header (the allow-list of cmake/SubdivPublicHeaders.cmake) includes only
#     installed headers and the standard library's, so it compiles for a user with nothing
#     but the installed package;
#  6. a front-end (tools/subdiv, python/src, plugins/paraview/filters) includes no file of
#     another front-end.
# Run: cmake -DSOURCE_DIR=<repo> -P check_layers.cmake
include(${SOURCE_DIR}/cmake/SubdivLayers.cmake)
include(${SOURCE_DIR}/cmake/SubdivPublicHeaders.cmake)
file(GLOB pipeline_headers RELATIVE ${SOURCE_DIR}/framework ${SOURCE_DIR}/framework/pipeline/*.h)
if(pipeline_headers AND SUBDIV_PIPELINE_PRIVATE_HEADERS)
  list(REMOVE_ITEM pipeline_headers ${SUBDIV_PIPELINE_PRIVATE_HEADERS})
endif()
set(public_headers ${SUBDIV_PUBLIC_HEADERS} ${SUBDIV_VTKIO_PUBLIC_HEADERS} ${pipeline_headers})
set(problems "")

function(included_framework_paths file out)
  file(STRINGS ${file} lines REGEX "^[ \t]*#[ \t]*include[ \t]+\"framework/")
  set(paths "")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]+\"framework/([^\"]+)\".*" "\\1" path "${line}")
    list(APPEND paths ${path})
  endforeach()
  set(${out} ${paths} PARENT_SCOPE)
endfunction()

foreach(layer IN LISTS SUBDIV_LAYERS)
  file(GLOB_RECURSE files ${SOURCE_DIR}/framework/${layer}/*.h ${SOURCE_DIR}/framework/${layer}/*.cpp)
  foreach(file IN LISTS files)
    file(RELATIVE_PATH rel ${SOURCE_DIR}/framework ${file})
    set(allowed ${layer} ${SUBDIV_LAYER_USES_${layer}})
    set(is_vtkio FALSE)
    if(rel MATCHES "^io/vtk/")
      set(allowed ${SUBDIV_VTKIO_USES})
      set(is_vtkio TRUE)
    endif()
    included_framework_paths(${file} paths)
    foreach(path IN LISTS paths)
      string(REGEX REPLACE "/.*" "" used "${path}")
      list(FIND allowed ${used} found)
      if(found EQUAL -1)
        string(REPLACE ";" ", " allowed_text "${allowed}")
        list(APPEND problems "framework/${rel} includes framework/${path}: layer '${layer}' may use only: ${allowed_text}")
      endif()
      if(path MATCHES "^io/vtk/" AND NOT is_vtkio)
        list(APPEND problems "framework/${rel} includes framework/${path}: only subdiv_vtkio (io/vtk) may; libsubdiv is VTK-free")
      endif()
      # Rooms: framework/<layer>/<room>/ may include earlier rooms of the same layer only.
      if(DEFINED SUBDIV_ROOMS_${layer} AND rel MATCHES "^${layer}/([a-z_]+)/" )
        set(rooms ${SUBDIV_ROOMS_${layer}})
        string(REGEX REPLACE "^${layer}/([a-z_]+)/.*" "\\1" my_room "${rel}")
        if(path MATCHES "^${layer}/([a-z_]+)/")
          string(REGEX REPLACE "^${layer}/([a-z_]+)/.*" "\\1" its_room "${path}")
          list(FIND rooms ${my_room} mine)
          list(FIND rooms ${its_room} its)
          if(its GREATER mine)
            list(APPEND problems "framework/${rel} includes framework/${path}: room ${layer}/${my_room} comes before ${layer}/${its_room}")
          endif()
        endif()
      endif()
    endforeach()
    if(NOT is_vtkio)
      file(STRINGS ${file} vtk_lines REGEX "^[ \t]*#[ \t]*include[ \t]+<vtk")
      if(vtk_lines)
        list(APPEND problems "framework/${rel} includes a VTK header: libsubdiv must stay VTK-free (VTK code goes to framework/io/vtk)")
      endif()
    endif()
    # Public headers must not pull internal or third-party ones into users' code.
    list(FIND public_headers ${rel} rel_public)
    if(NOT rel_public EQUAL -1)
      foreach(path IN LISTS paths)
        list(FIND public_headers ${path} public)
        if(public EQUAL -1)
          list(APPEND problems "framework/${rel} is installed but includes framework/${path}, which is not (cmake/SubdivPublicHeaders.cmake)")
        endif()
      endforeach()
      file(STRINGS ${file} other_lines REGEX "^[ \t]*#[ \t]*include[ \t]*<[^>]*[./][^>]*>")
      foreach(line IN LISTS other_lines)
        list(APPEND problems "framework/${rel} is installed but includes a third-party header: ${line}")
      endforeach()
    endif()
  endforeach()
endforeach()

# A folder under framework/ that is not in the table would escape every check.
file(GLOB top_folders LIST_DIRECTORIES true ${SOURCE_DIR}/framework/*)
foreach(folder IN LISTS top_folders)
  if(IS_DIRECTORY ${folder})
    get_filename_component(name ${folder} NAME)
    list(FIND SUBDIV_LAYERS ${name} known)
    if(known EQUAL -1)
      list(APPEND problems "framework/${name}/ is not a layer of cmake/SubdivLayers.cmake: add it there with the layers it uses")
    endif()
  endif()
endforeach()

# 6. The front-ends (the command line, the Python module, the ParaView filters) stand side by
#    side on the library: each includes framework/ headers, the reports library and its own
#    folder's files, never a file of another front-end (they share framework/pipeline).
foreach(front_end tools/subdiv python/src plugins/paraview/filters)
  file(GLOB files ${SOURCE_DIR}/${front_end}/*.h ${SOURCE_DIR}/${front_end}/*.cpp ${SOURCE_DIR}/${front_end}/*.cxx)
  foreach(file IN LISTS files)
    file(STRINGS ${file} lines REGEX "^[ \t]*#[ \t]*include[ \t]+\"")
    foreach(line IN LISTS lines)
      string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]+\"([^\"]+)\".*" "\\1" path "${line}")
      # Also allowed: the reports library all three may use (tools/reports: text, JSON, SVG of
      # analysis results), VTK's headers and the module header VTK generates for the filters.
      if(path MATCHES "^framework/" OR EXISTS ${SOURCE_DIR}/${front_end}/${path} OR
         EXISTS ${SOURCE_DIR}/tools/reports/${path} OR path MATCHES "^vtk" OR path MATCHES "Module\\.h$")
        continue()
      endif()
      file(RELATIVE_PATH rel ${SOURCE_DIR} ${file})
      list(APPEND problems "${rel} includes \"${path}\", which is neither framework/ nor a file of ${front_end}: front-ends share only the library (framework/pipeline)")
    endforeach()
  endforeach()
endforeach()

if(problems)
  list(LENGTH problems count)
  string(REPLACE ";" "\n  " text "${problems}")
  message(FATAL_ERROR "${count} layering problem(s):\n  ${text}")
endif()
message(STATUS "layers hold: every framework include follows cmake/SubdivLayers.cmake")
