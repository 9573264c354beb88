// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

// Loading the GL function table (gl_functions.h), for the context files: they include
// their window system's own GL headers, which must not meet the table's.

#include <string>

namespace meshfair::gl {

//! A function address by its full name ("glBindBuffer"), from the context's loader.
using ProcAddress = void* (*)(const char* name);

//! \brief Fills the table from `proc_address` for the context current on this thread and
//! checks that it is OpenGL 3.3 or later. Returns the GL_RENDERER string.
//! \throw RenderError naming the missing function or the version found. (OSMesa returns
//! non-null stubs even for unknown names, hence the version check.)
std::string load_functions(ProcAddress proc_address);

} // namespace meshfair::gl
