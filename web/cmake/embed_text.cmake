# cmake -DOUT=header -DNAMESPACE=essi::shaders -DFROM="shaders/*.glsl" -DFILES="a.glsl;b.glsl" -P embed_text.cmake
# Writes a header with one `inline constexpr const char* <name>` per file (its name with every character but
# letters and digits made `_`, as a raw string literal) and `kFiles`, every file's name and text in the order given:
# the native and web builds compile exactly the same text (the shaders' GLSL, the warm-up's tapes).
set(_text "// Generated from ${FROM} by web/cmake/embed_text.cmake. Do not edit.\n#pragma once\n\nnamespace ${NAMESPACE} {\n")
set(_table "")
foreach(_f IN LISTS FILES)
  get_filename_component(_name ${_f} NAME)
  string(REGEX REPLACE "[^A-Za-z0-9]" "_" _id ${_name})
  file(READ ${_f} _src)
  string(APPEND _text "\n// ${_name}\ninline constexpr const char* ${_id} = R\"essi_text(${_src})essi_text\";\n")
  string(APPEND _table "    {\"${_name}\", ${_id}},\n")
endforeach()
string(APPEND _text "\nstruct EmbeddedFile {\n    const char* name;\n    const char* text;\n};\n")
string(APPEND _text "inline constexpr EmbeddedFile kFiles[] = {\n${_table}};\n")
string(APPEND _text "\n}  // namespace ${NAMESPACE}\n")
file(WRITE ${OUT}.tmp "${_text}")
file(COPY_FILE ${OUT}.tmp ${OUT} ONLY_IF_DIFFERENT)
