# cmake -DOUT=header -DFILES="a.glsl;b.glsl" -P embed_shaders.cmake
# Writes a header with one `inline constexpr const char* k<Name>` per shader file (raw string literals), so the
# native and web builds compile exactly the same GLSL text (#version 300 es).
set(_text "// Generated from shaders/*.glsl by web/cmake/embed_shaders.cmake. Do not edit.\n#pragma once\n\nnamespace essi::shaders {\n")
foreach(_f IN LISTS FILES)
  get_filename_component(_name ${_f} NAME)
  string(REGEX REPLACE "[^A-Za-z0-9]" "_" _id ${_name})
  file(READ ${_f} _src)
  string(APPEND _text "\n// ${_name}\ninline constexpr const char* ${_id} = R\"essi_glsl(${_src})essi_glsl\";\n")
endforeach()
string(APPEND _text "\n}  // namespace essi::shaders\n")
file(WRITE ${OUT}.tmp "${_text}")
file(COPY_FILE ${OUT}.tmp ${OUT} ONLY_IF_DIFFERENT)
