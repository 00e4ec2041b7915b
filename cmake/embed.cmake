# socsim_embed_files(<out_var> NAMESPACE ns FUNCTION fn BASE dir GLOBS pattern...):
# generates a C++ source defining `const std::map<std::string, std::string>& ns::fn()` that maps
# each matching file's path relative to BASE to its bytes (cmake/embed_files.cmake), so the
# binary carries its migrations, prompt templates and schemas wherever it runs. The source's
# path is stored in <out_var>; add it to a target's sources.
function(socsim_embed_files out_var)
  cmake_parse_arguments(E "" "NAMESPACE;FUNCTION;BASE" "GLOBS" ${ARGN})
  file(GLOB files CONFIGURE_DEPENDS ${E_GLOBS})
  list(SORT files)
  string(REPLACE ";" "|" file_list "${files}")  # a ; would split the command line
  set(out ${CMAKE_CURRENT_BINARY_DIR}/${E_FUNCTION}.cpp)
  add_custom_command(
    OUTPUT ${out}
    COMMAND ${CMAKE_COMMAND} -DOUT=${out} -DNAMESPACE=${E_NAMESPACE} -DFUNCTION=${E_FUNCTION} "-DFILES=${file_list}"
            -DBASE=${E_BASE} -P ${PROJECT_SOURCE_DIR}/cmake/embed_files.cmake
    DEPENDS ${files} ${PROJECT_SOURCE_DIR}/cmake/embed_files.cmake
    COMMENT "Embedding ${E_FUNCTION}"
    VERBATIM)
  set(${out_var} ${out} PARENT_SCOPE)
endfunction()
