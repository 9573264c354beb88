// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <initializer_list>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "app/render/gl_functions.h"

namespace meshfair::gl {

//! \brief A linked shader program of the files in shaders/ (embedded at build time), with
//! its uniforms' locations looked up once.
class Program
{
public:
    //! \brief Compiles `<name>.vert`, `<name>.geom` when `with_geometry`, and `<name>.frag`,
    //! links them and checks that every name in `uniforms` is an active uniform.
    //! \throw RenderError with the compiler's or linker's log, or the missing uniform.
    Program(std::string_view name, bool with_geometry, std::initializer_list<const char*> uniforms);
    //! \brief The same with `defines` (lines of `#define NAME`) put after each file's
    //! #version line: one of the variants a file's #ifdef blocks make.
    Program(std::string_view name, bool with_geometry, const std::vector<const char*>& uniforms,
            std::string_view defines);
    ~Program();
    Program(const Program&) = delete;
    Program& operator=(const Program&) = delete;

    void use() const;
    //! The location of a uniform named at construction.
    GLint operator[](const char* uniform) const;

private:
    std::string name_;
    GLuint id_ = 0;
    std::unordered_map<std::string, GLint> uniforms_;
};

//! The text of an embedded shader file ("mesh.vert"), empty if there is none.
std::string_view shader_source(std::string_view file);

} // namespace meshfair::gl
