# The source tree matches the explicit lists of core/CMakeLists.txt, ui/CMakeLists.txt and
# app/CMakeLists.txt (core/README.md, ui/README.md): every .h, .cpp and .inc under DIRS is
# listed in LISTED_FILE (one absolute path a line), every listed file exists, and no file
# lies directly in a folder of DIRS but its CMakeLists.txt and README.md — except in the
# folders of FLAT_DIRS (app/, whose gui_main.cpp is the GUI's entry point), whose direct
# files need only be listed.
cmake_minimum_required(VERSION 3.25)
file(STRINGS ${LISTED_FILE} listed)
set(problems)
foreach(dir ${DIRS})
  file(GLOB direct LIST_DIRECTORIES false RELATIVE ${SOURCE_DIR} ${SOURCE_DIR}/${dir}/*)
  foreach(f ${direct})
    if(NOT f MATCHES "/(CMakeLists\\.txt|README\\.md)$" AND NOT dir IN_LIST FLAT_DIRS)
      list(APPEND problems "directly in ${dir}/ (put it in the folder of its concept): ${f}")
    endif()
  endforeach()
  file(GLOB_RECURSE on_disk ${SOURCE_DIR}/${dir}/*.h ${SOURCE_DIR}/${dir}/*.cpp ${SOURCE_DIR}/${dir}/*.inc)
  foreach(f ${on_disk})
    if(NOT f IN_LIST listed)
      list(APPEND problems "not in the source list of ${dir}/CMakeLists.txt: ${f}")
    endif()
  endforeach()
endforeach()
foreach(f ${listed})
  if(NOT EXISTS ${f})
    list(APPEND problems "listed but missing: ${f}")
  endif()
endforeach()
if(problems)
  list(JOIN problems "\n" text)
  message(FATAL_ERROR "${text}")
endif()
