# Script mode: writes OUT with a map from shader name to source text.
file(GLOB_RECURSE files RELATIVE ${SHADER_DIR}
     ${SHADER_DIR}/*.vert ${SHADER_DIR}/*.frag ${SHADER_DIR}/*.geom ${SHADER_DIR}/*.comp ${SHADER_DIR}/*.glsl)
list(SORT files)
set(body "")
foreach(f ${files})
  file(READ ${SHADER_DIR}/${f} text)
  string(APPEND body "    {\"${f}\", R\"FLOWSURF_GLSL(${text})FLOWSURF_GLSL\"},\n")
endforeach()
file(WRITE ${OUT}.tmp "// Generated from shaders/ by cmake/EmbedShadersRun.cmake. Do not edit.
#include <map>
#include <string>
namespace flowsurf::gl {
const std::map<std::string, std::string>& embeddedShaders() {
  static const std::map<std::string, std::string> shaders = {
${body}  };
  return shaders;
}
}  // namespace flowsurf::gl
")
file(RENAME ${OUT}.tmp ${OUT})
