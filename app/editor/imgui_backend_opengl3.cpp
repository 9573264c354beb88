// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
//
// Dear ImGui's OpenGL 3 backend, compiled from the source Debian ships under
// /usr/share/doc/libimgui-dev/examples/backends/ (its include directory is added for this
// file only), with MeshFair's GL function table as its loader: the backend inside
// libimgui.a loads GL through libGL/GLX and cannot draw into OSMesa.
#include "app/render/gl_functions.h"

#define IMGUI_IMPL_OPENGL_LOADER_CUSTOM
#include "imgui_impl_opengl3.cpp"
