# Checks that each room of src/geompm (and its unit tests, tests/unit/<room>) includes only the
# rooms it may use (CMakeLists.txt: geompm_room(<room> ROOMS ...), closed over what those may
# use). Run by the build (target geompm_room_check) and by the unit tier (test rooms.includes):
#   cmake -DROOMS_FILE=<build>/geompm_rooms.cmake -DSOURCE_DIR=<source> -P check_rooms.cmake
# ROOMS_FILE sets GEOMPM_ROOMS (every room) and GEOMPM_ROOM_ALLOWED_<room> (the rooms it may
# include, itself among them). A test's quoted include of a file of tests/support (run_model.hpp)
# is followed, so a unit test cannot reach a higher room through a support header.
cmake_minimum_required(VERSION 3.25)
include(${ROOMS_FILE})

set(violations "")

# Appends to `violations` every include of a room outside `room`'s allowed list in `file`, and
# follows its includes of test support headers (to `depth` levels: they include one another
# little, and never in a cycle that deep).
function(check_file room file via depth)
  file(STRINGS ${file} lines REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
  foreach(line IN LISTS lines)
    string(REGEX MATCH "\"([^\"]+)\"" ignored "${line}")
    set(included "${CMAKE_MATCH_1}")
    if(included MATCHES "^geompm/([^/]+)/")
      set(target "${CMAKE_MATCH_1}")
      if(NOT target IN_LIST GEOMPM_ROOM_ALLOWED_${room})
        file(RELATIVE_PATH shown ${SOURCE_DIR} ${file})
        string(JOIN ", " may ${GEOMPM_ROOM_ALLOWED_${room}})
        string(APPEND violations "\n  ${shown}${via}: room '${room}' includes \"${included}\" "
               "(room '${target}'); it may use: ${may}")
      endif()
    elseif(EXISTS ${SOURCE_DIR}/tests/support/${included})
      if(depth LESS 4)
        math(EXPR deeper "${depth} + 1")
        file(RELATIVE_PATH from ${SOURCE_DIR} ${file})
        if(via)
          set(from_via "${via}")
        else()
          set(from_via " (included by ${from})")
        endif()
        check_file(${room} ${SOURCE_DIR}/tests/support/${included} "${from_via}" ${deeper})
      endif()
    endif()
  endforeach()
  set(violations "${violations}" PARENT_SCOPE)
endfunction()

foreach(room IN LISTS GEOMPM_ROOMS)
  file(GLOB_RECURSE files ${SOURCE_DIR}/src/geompm/${room}/*.hpp ${SOURCE_DIR}/src/geompm/${room}/*.cpp
       ${SOURCE_DIR}/tests/unit/${room}/*.hpp ${SOURCE_DIR}/tests/unit/${room}/*.cpp)
  foreach(file IN LISTS files)
    check_file(${room} ${file} "" 0)
  endforeach()
endforeach()

# A directory of src/geompm or tests/unit that is no room escapes the check: it must be declared.
file(GLOB dirs LIST_DIRECTORIES true ${SOURCE_DIR}/src/geompm/* ${SOURCE_DIR}/tests/unit/*)
foreach(dir IN LISTS dirs)
  get_filename_component(name ${dir} NAME)
  if(IS_DIRECTORY ${dir} AND NOT name IN_LIST GEOMPM_ROOMS)
    file(RELATIVE_PATH shown ${SOURCE_DIR} ${dir})
    string(APPEND violations "\n  ${shown}: not a room (declare it with geompm_room in "
           "CMakeLists.txt)")
  endif()
endforeach()

if(violations)
  message(FATAL_ERROR "Includes across rooms that the layering forbids "
                      "(docs/architecture.md, Rooms):${violations}")
endif()
