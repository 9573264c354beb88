// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
//
// Dear ImGui's GLFW platform backend, compiled from the source Debian ships under
// /usr/share/doc/libimgui-dev/examples/backends/ (see imgui_backend_opengl3.cpp). GLFW's
// header must not pull in GL/gl.h, whose prototypes would clash with the GL table.
#define GLFW_INCLUDE_NONE
#include "imgui_impl_glfw.cpp"
