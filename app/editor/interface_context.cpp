// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/interface_context.h"

#include <imgui.h>

#include <backends/imgui_impl_opengl3.h>

#include "app/editor/input_event.h"
#include "app/render/render_error.h"

namespace meshfair::app {

InterfaceContext::InterfaceContext(bool draws) : draws_(draws)
{
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.LogFilename = nullptr;
    // ImGui's keys in MeshFair's codes, which are GLFW's.
    io.KeyMap[ImGuiKey_Tab] = key::Tab;
    io.KeyMap[ImGuiKey_LeftArrow] = key::Left;
    io.KeyMap[ImGuiKey_RightArrow] = key::Right;
    io.KeyMap[ImGuiKey_UpArrow] = key::Up;
    io.KeyMap[ImGuiKey_DownArrow] = key::Down;
    io.KeyMap[ImGuiKey_PageUp] = key::PageUp;
    io.KeyMap[ImGuiKey_PageDown] = key::PageDown;
    io.KeyMap[ImGuiKey_Home] = key::Home;
    io.KeyMap[ImGuiKey_End] = key::End;
    io.KeyMap[ImGuiKey_Insert] = key::Insert;
    io.KeyMap[ImGuiKey_Delete] = key::Delete;
    io.KeyMap[ImGuiKey_Backspace] = key::Backspace;
    io.KeyMap[ImGuiKey_Space] = key::Space;
    io.KeyMap[ImGuiKey_Enter] = key::Enter;
    io.KeyMap[ImGuiKey_Escape] = key::Escape;
    io.KeyMap[ImGuiKey_KeyPadEnter] = key::KeypadEnter;
    io.KeyMap[ImGuiKey_A] = key::Letter('a');
    io.KeyMap[ImGuiKey_C] = key::Letter('c');
    io.KeyMap[ImGuiKey_V] = key::Letter('v');
    io.KeyMap[ImGuiKey_X] = key::Letter('x');
    io.KeyMap[ImGuiKey_Y] = key::Letter('y');
    io.KeyMap[ImGuiKey_Z] = key::Letter('z');
    ImGui::StyleColorsDark();
    ImGui::GetStyle().WindowRounding = 0;
    if (!draws_)
    {
        unsigned char* pixels = nullptr;
        int width = 0, height = 0;
        io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height); // builds the atlas
        return;
    }
    if (!ImGui_ImplOpenGL3_Init("#version 330 core"))
    {
        ImGui::DestroyContext();
        throw RenderError("Dear ImGui's OpenGL 3 backend did not start");
    }
}

InterfaceContext::~InterfaceContext()
{
    if (draws_)
        ImGui_ImplOpenGL3_Shutdown();
    ImGui::DestroyContext();
}

void InterfaceContext::new_frame()
{
    if (draws_)
        ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
}

void InterfaceContext::end_frame()
{
    ImGui::Render();
}

void InterfaceContext::draw()
{
    if (draws_)
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

} // namespace meshfair::app
