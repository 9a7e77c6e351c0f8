# Embeds every file under shaders/ into a generated C++ source as raw strings, so the
# binaries need no shader files at run time. Names are paths relative to shaders/.
# Paths are relative to this file, so the ParaView plugin's own project (src/paraview) can
# embed the same shaders.
set(FLOWSURF_CMAKE_DIR ${CMAKE_CURRENT_LIST_DIR})
function(flowsurf_embed_shaders target)
  file(GLOB_RECURSE shader_files CONFIGURE_DEPENDS ${FLOWSURF_CMAKE_DIR}/../shaders/*.geom
       ${FLOWSURF_CMAKE_DIR}/../shaders/*.vert ${FLOWSURF_CMAKE_DIR}/../shaders/*.frag
       ${FLOWSURF_CMAKE_DIR}/../shaders/*.comp ${FLOWSURF_CMAKE_DIR}/../shaders/*.glsl)
  set(out ${CMAKE_CURRENT_BINARY_DIR}/embedded_shaders.cpp)
  add_custom_command(
    OUTPUT ${out}
    COMMAND ${CMAKE_COMMAND} -DSHADER_DIR=${FLOWSURF_CMAKE_DIR}/../shaders -DOUT=${out}
            -P ${FLOWSURF_CMAKE_DIR}/EmbedShadersRun.cmake
    DEPENDS ${shader_files} ${FLOWSURF_CMAKE_DIR}/EmbedShadersRun.cmake
    COMMENT "Embedding shaders")
  target_sources(${target} PRIVATE ${out})
endfunction()
