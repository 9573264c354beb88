// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/render/gl_program.h"

#include <algorithm>
#include <vector>

#include "app/render/render_error.h"

namespace meshfair::gl {

namespace {

// A shader's or a program's info log (the compiler's or the linker's messages).
template <class GetParameter, class GetLog>
std::string info_log(GLuint object, GetParameter get_parameter, GetLog get_log)
{
    GLint size = 0;
    get_parameter(object, GL_INFO_LOG_LENGTH, &size);
    std::vector<char> log(static_cast<size_t>(size) + 1, '\0');
    get_log(object, size, nullptr, log.data());
    return log.data();
}

GLuint compile(const std::string& file, GLenum stage, std::string_view defines)
{
    const std::string_view source = shader_source(file);
    if (source.empty())
        throw app::RenderError("no embedded shader '" + file + "'");
    // The defines go after the first line, the #version directive.
    const size_t first_line = std::min(source.find('\n'), source.size());
    const std::string_view version = source.substr(0, first_line);
    const std::string_view rest = source.substr(first_line);
    const std::string newline = "\n";
    const char* texts[] = {version.data(), newline.data(), defines.empty() ? "" : defines.data(),
                           rest.data()};
    const GLint lengths[] = {static_cast<GLint>(version.size()), 1,
                             static_cast<GLint>(defines.size()), static_cast<GLint>(rest.size())};
    const GLuint shader = glCreateShader(stage);
    glShaderSource(shader, 4, texts, lengths);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE)
    {
        const std::string log = info_log(shader, glGetShaderiv, glGetShaderInfoLog);
        glDeleteShader(shader);
        throw app::RenderError("shaders/" + file + " does not compile: " + log);
    }
    return shader;
}

} // namespace

Program::Program(std::string_view name, bool with_geometry,
                 std::initializer_list<const char*> uniforms)
    : Program(name, with_geometry, std::vector<const char*>(uniforms), {})
{
}

Program::Program(std::string_view name, bool with_geometry,
                 const std::vector<const char*>& uniforms, std::string_view defines)
    : name_(name)
{
    std::vector<GLuint> shaders{compile(name_ + ".vert", GL_VERTEX_SHADER, defines)};
    if (with_geometry)
        shaders.push_back(compile(name_ + ".geom", GL_GEOMETRY_SHADER, defines));
    shaders.push_back(compile(name_ + ".frag", GL_FRAGMENT_SHADER, defines));
    id_ = glCreateProgram();
    for (const GLuint s : shaders)
        glAttachShader(id_, s);
    glLinkProgram(id_);
    for (const GLuint s : shaders)
    {
        glDetachShader(id_, s);
        glDeleteShader(s);
    }
    GLint ok = GL_FALSE;
    glGetProgramiv(id_, GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE)
    {
        const std::string log = info_log(id_, glGetProgramiv, glGetProgramInfoLog);
        glDeleteProgram(id_);
        throw app::RenderError("shader program '" + name_ + "' does not link: " + log);
    }
    for (const char* u : uniforms)
    {
        const GLint location = glGetUniformLocation(id_, u);
        if (location < 0)
        {
            glDeleteProgram(id_);
            throw app::RenderError("shader program '" + name_ + "' has no uniform " + u);
        }
        uniforms_[u] = location;
    }
}

Program::~Program()
{
    glDeleteProgram(id_);
}

void Program::use() const
{
    glUseProgram(id_);
}

GLint Program::operator[](const char* uniform) const
{
    const auto it = uniforms_.find(uniform);
    if (it == uniforms_.end())
        throw app::RenderError("shader program '" + name_ + "': uniform " + uniform +
                               " was not declared");
    return it->second;
}

} // namespace meshfair::gl
