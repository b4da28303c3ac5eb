# Every class, struct and enum class that core/, ui/ and app/ declare at namespace level has a
# name of its own. Two types of one name in one namespace break the one-definition rule: the
# program links, and then a vector of one is freed as a vector of the other (AddressSanitizer
# saw granota::AngleLimit of the scene parameters and of the XPBD chains do exactly that).
#   cmake -DSOURCE_DIR=… -P check_unique_type_names.cmake
file(GLOB_RECURSE headers ${SOURCE_DIR}/core/*.h ${SOURCE_DIR}/ui/*.h ${SOURCE_DIR}/app/*.h)
set(seen "")
set(clashes "")
foreach(header ${headers})
  file(STRINGS ${header} lines REGEX "^(struct|class|enum class|enum) [A-Za-z_][A-Za-z0-9_]*( final)? *(\\{|:|$)")
  foreach(line ${lines})
    string(REGEX REPLACE "^(struct|class|enum class|enum) ([A-Za-z_][A-Za-z0-9_]*).*" "\\2" name "${line}")
    file(RELATIVE_PATH where ${SOURCE_DIR} ${header})
    if(DEFINED where_${name} AND NOT where_${name} STREQUAL where)
      list(APPEND clashes "${name}: ${where_${name}} and ${where}")
    endif()
    set(where_${name} ${where})
  endforeach()
endforeach()
if(clashes)
  list(JOIN clashes "\n  " text)
  message(FATAL_ERROR "types declared twice under one name:\n  ${text}")
endif()
list(LENGTH headers count)
message(STATUS "${count} headers, every type name declared once")
