// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/interface_context.h"

#include <imgui.h>

#include <backends/imgui_impl_opengl3.h>

#include "app/render/render_error.h"

namespace meshfair::app {

InterfaceContext::InterfaceContext()
{
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.LogFilename = nullptr;
    ImGui::StyleColorsDark();
    ImGui::GetStyle().WindowRounding = 0;
    if (!ImGui_ImplOpenGL3_Init("#version 330 core"))
    {
        ImGui::DestroyContext();
        throw RenderError("Dear ImGui's OpenGL 3 backend did not start");
    }
}

InterfaceContext::~InterfaceContext()
{
    ImGui_ImplOpenGL3_Shutdown();
    ImGui::DestroyContext();
}

void InterfaceContext::new_frame()
{
    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
}

void InterfaceContext::end_frame()
{
    ImGui::Render();
}

void InterfaceContext::draw()
{
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

} // namespace meshfair::app
