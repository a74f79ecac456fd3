# Turns a text file into C++: `std::string_view FUNCTION()` returning its bytes exactly as they are
# (no line-end conversion, no escaping to get wrong), for the scripts jelly-grade writes
# (grader/CMakeLists.txt). Run as
#   cmake -DINPUT=file -DOUTPUT=file.cpp -DFUNCTION=name -DHEADER=header.hpp -P embed.cmake
foreach(var INPUT OUTPUT FUNCTION HEADER)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "embed.cmake: -D${var}=... is missing")
  endif()
endforeach()
file(READ "${INPUT}" hex HEX)
if(hex STREQUAL "")
  message(FATAL_ERROR "embed.cmake: ${INPUT} is empty")
endif()
string(LENGTH "${hex}" digits)
math(EXPR size "${digits} / 2")
# 16 bytes a line: "    0x23, 0x21, ...,"
set(bytes "")
set(pos 0)
while(pos LESS digits)
  string(SUBSTRING "${hex}" ${pos} 32 line)
  string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1, " line "${line}")
  string(REGEX REPLACE " $" "" line "${line}")
  string(APPEND bytes "    ${line}\n")
  math(EXPR pos "${pos} + 32")
endwhile()
get_filename_component(shown "${INPUT}" NAME)
set(text "// Generated from grader/templates/${shown} by grader/templates/embed.cmake: edit the template, not this.
#include \"${HEADER}\"

namespace jelly::grade {

namespace {
const unsigned char kBytes[${size}] = {
${bytes}};
}  // namespace

std::string_view ${FUNCTION}() {
  return {reinterpret_cast<const char*>(kBytes), sizeof kBytes};
}

}  // namespace jelly::grade
")
file(WRITE "${OUTPUT}" "${text}")
