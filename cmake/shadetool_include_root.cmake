# shadetool_include_root(LIB_DIR OUT_VAR): makes ${CMAKE_BINARY_DIR}/include/shadetool a link to
# LIB_DIR (the source tree's lib/) and sets OUT_VAR to ${CMAKE_BINARY_DIR}/include, so that sources
# in the build tree include the library exactly as an installed consumer does:
# #include <shadetool/normals/vertex_normals.h>. lib/ itself is never on the include path.
function(shadetool_include_root lib_dir out_var)
  set(root ${CMAKE_BINARY_DIR}/include)
  file(MAKE_DIRECTORY ${root})
  if(IS_SYMLINK ${root}/shadetool)
    file(REMOVE ${root}/shadetool)
  endif()
  file(CREATE_LINK ${lib_dir} ${root}/shadetool SYMBOLIC)
  set(${out_var} ${root} PARENT_SCOPE)
endfunction()
