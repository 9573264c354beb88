# SPDX-License-Identifier: MIT
# Writes OUTPUT, a C++ file defining meshfair::gl::shader_source(file) over the shader
# files given in SHADERS (paths separated by '|'), so that the programs never read shaders/
# at run time. Run as `cmake -DOUTPUT=... -DSHADERS=... -P embed_shaders.cmake`.
set(body "")
string(REPLACE "|" ";" shader_paths "${SHADERS}")
foreach(path IN LISTS shader_paths)
    get_filename_component(file "${path}" NAME)
    file(READ "${path}" text)
    string(APPEND body "        {\"${file}\", R\"meshfair_glsl(${text})meshfair_glsl\"},\n")
endforeach()
file(WRITE "${OUTPUT}.tmp" "// Generated from shaders/ by cmake/embed_shaders.cmake; do not edit.
#include <string_view>
#include <utility>

namespace meshfair::gl {

std::string_view shader_source(std::string_view file)
{
    static constexpr std::pair<std::string_view, std::string_view> kFiles[] = {
${body}    };
    for (const auto& [name, text] : kFiles)
        if (name == file)
            return text;
    return {};
}

} // namespace meshfair::gl
")
# Only a changed text touches the output, so an unchanged shader rebuilds nothing.
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUTPUT}.tmp")
