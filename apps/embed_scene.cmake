# cmake -DINPUT=scene.json -DOUTPUT=header.hpp -P embed_scene.cmake
# Writes a header holding the scene file's text, so that an app carries its default scene.
file(READ "${INPUT}" text)
get_filename_component(name "${INPUT}" NAME)
if(text MATCHES "\\)__scene__\"")
  message(FATAL_ERROR "${INPUT} contains the raw-string delimiter )__scene__\"")
endif()
file(WRITE "${OUTPUT}.tmp"
  "// Generated at build time from scenes/${name}; edit the scene file, not this header.\n"
  "#pragma once\n"
  "inline constexpr const char* kDefaultSceneName = \"${name}\";\n"
  "inline constexpr const char* kDefaultScene = R\"__scene__(${text})__scene__\";\n")
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUTPUT}.tmp")
