// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/render/gl_functions.h"

#include <cstdio>

#include "app/render/render_error.h"

namespace meshfair::gl {

Functions g_functions;

std::string load_functions(ProcAddress proc_address)
{
    Functions f;
#define MESHFAIR_GL_LOAD(type, name)                           \
    f.name = reinterpret_cast<type>(proc_address("gl" #name)); \
    if (f.name == nullptr)                                     \
        throw app::RenderError("OpenGL function gl" #name " is missing from the context");
    MESHFAIR_GL_FUNCTIONS(MESHFAIR_GL_LOAD)
#undef MESHFAIR_GL_LOAD
    GLint major = 0, minor = 0;
    f.GetIntegerv(GL_MAJOR_VERSION, &major);
    f.GetIntegerv(GL_MINOR_VERSION, &minor);
    const auto* version = reinterpret_cast<const char*>(f.GetString(GL_VERSION));
    if (version == nullptr || major * 10 + minor < 33)
        throw app::RenderError(std::string("OpenGL 3.3 core is needed; the context gives ") +
                               (version ? version : "no version"));
    g_functions = f;
    const auto* renderer = reinterpret_cast<const char*>(f.GetString(GL_RENDERER));
    return renderer ? renderer : "unknown renderer";
}

} // namespace meshfair::gl
