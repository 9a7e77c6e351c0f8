# Embeds every file under shaders/ into a generated C++ source as raw strings, so the
# binaries need no shader files at run time. Names are paths relative to shaders/.
function(flowsurf_embed_shaders target)
  file(GLOB_RECURSE shader_files CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/shaders/*.geom
       ${PROJECT_SOURCE_DIR}/shaders/*.vert ${PROJECT_SOURCE_DIR}/shaders/*.frag
       ${PROJECT_SOURCE_DIR}/shaders/*.comp ${PROJECT_SOURCE_DIR}/shaders/*.glsl)
  set(out ${CMAKE_CURRENT_BINARY_DIR}/embedded_shaders.cpp)
  add_custom_command(
    OUTPUT ${out}
    COMMAND ${CMAKE_COMMAND} -DSHADER_DIR=${PROJECT_SOURCE_DIR}/shaders -DOUT=${out}
            -P ${PROJECT_SOURCE_DIR}/cmake/EmbedShadersRun.cmake
    DEPENDS ${shader_files} ${PROJECT_SOURCE_DIR}/cmake/EmbedShadersRun.cmake
    COMMENT "Embedding shaders")
  target_sources(${target} PRIVATE ${out})
endfunction()
