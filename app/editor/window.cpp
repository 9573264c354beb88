// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/window.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <utility>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <backends/imgui_impl_glfw.h>

#include "app/editor/document.h"
#include "app/editor/editor_session.h"
#include "app/editor/editor_ui.h"
#include "app/editor/interface_context.h"
#include "app/editor/navigation.h"
#include "app/render/gl_loader.h"
#include "app/render/gl_renderer.h"
#include "app/render/render_error.h"
#include "core/errors.h"
#include "core/io/io.h"

namespace meshfair::app {

namespace {

std::string g_glfw_error; // GLFW reports errors through a C callback, before any window

void remember_glfw_error(int /*code*/, const char* description)
{
    g_glfw_error = description ? description : "unknown GLFW error";
}

void* glfw_proc_address(const char* name)
{
    return reinterpret_cast<void*>(glfwGetProcAddress(name));
}

// Everything a frame needs, reachable from GLFW's C callbacks through the user pointer.
struct Editor
{
    GLFWwindow* window = nullptr;
    EditorUi ui;
    std::unique_ptr<GlRenderer> renderer;
    std::unique_ptr<EditorSession> session; // after the renderer: it draws with it
    UiRequests pending; // requests from keys and callbacks, merged with the UI's
    std::string screenshot_path;
    int screenshots = 0;

    //! The cursor in the view's pixels.
    void cursor(double& x, double& y) const
    {
        // Window coordinates to framebuffer pixels (they differ on scaled displays).
        const ViewRect& view = session->view_rect();
        int ww = 0, wh = 0;
        glfwGetWindowSize(window, &ww, &wh);
        glfwGetCursorPos(window, &x, &y);
        x = x * view.framebuffer_width / std::max(ww, 1) - view.x;
        y = y * view.framebuffer_height / std::max(wh, 1) - view.y;
    }

    void screenshot()
    {
        std::string path = screenshot_path;
        if (path.empty())
            path = "meshfair-screenshot-" + std::to_string(++screenshots) + ".png";
        const ViewRect& view = session->view_rect();
        try
        {
            write_png(renderer->read_pixels(view.framebuffer_width, view.framebuffer_height), path);
            session->state().message = "screenshot " + path;
        }
        catch (const std::exception& e)
        {
            session->state().message = e.what();
        }
    }

    void carry_out(const UiRequests& r)
    {
        session->carry_out(r);
        if (r.quit)
            glfwSetWindowShouldClose(window, GLFW_TRUE);
    }
};

Editor& editor_of(GLFWwindow* window)
{
    return *static_cast<Editor*>(glfwGetWindowUserPointer(window));
}

void on_key(GLFWwindow* window, int key, int /*scancode*/, int action, int mods)
{
    if (action != GLFW_PRESS && action != GLFW_REPEAT)
        return;
    Editor& e = editor_of(window);
    if (ImGui::GetIO().WantCaptureKeyboard)
        return;
    const bool ctrl = mods & GLFW_MOD_CONTROL, shift = mods & GLFW_MOD_SHIFT,
               alt = mods & GLFW_MOD_ALT;
    UiRequests& r = e.pending;
    EditorState& state = e.session->state();
    DisplayOptions& d = state.display;
    const Document& document = e.session->document();
    switch (key)
    {
        case GLFW_KEY_Q:
            if (ctrl)
                e.ui.ask_to_quit(document, r);
            break;
        case GLFW_KEY_O:
            if (ctrl)
                e.ui.open_file_dialog(document);
            break;
        case GLFW_KEY_S:
            if (ctrl && shift)
                e.ui.save_file_dialog(document);
            else if (ctrl)
                r.save_path = document.path; // Save: the file it came from, in its format
            else
                d.shading = d.shading == Shading::Smooth ? Shading::Flat : Shading::Smooth;
            break;
        case GLFW_KEY_Z:
            if (ctrl)
                (shift ? r.redo : r.undo) = true;
            break;
        case GLFW_KEY_Y:
            if (ctrl)
                r.redo = true;
            break;
        case GLFW_KEY_A:
            if (ctrl)
                r.command = SelectionCommand::All;
            else if (alt)
                r.command = SelectionCommand::Clear;
            else if (shift)
                r.create_set = ConstraintKind::Anchor;
            break;
        case GLFW_KEY_I:
            if (ctrl)
                r.command = SelectionCommand::Invert;
            break;
        case GLFW_KEY_EQUAL:
        case GLFW_KEY_KP_ADD:
            if (ctrl)
                r.command = SelectionCommand::Grow;
            break;
        case GLFW_KEY_MINUS:
        case GLFW_KEY_KP_SUBTRACT:
            if (ctrl)
                r.command = SelectionCommand::Shrink;
            break;
        case GLFW_KEY_L:
            if (ctrl)
                r.command = SelectionCommand::Connected;
            else
                r.tool = ToolKind::Lasso;
            break;
        case GLFW_KEY_N:
            if (shift)
                r.create_set = ConstraintKind::Normal;
            else
                r.tool = ToolKind::Navigate;
            break;
        case GLFW_KEY_E:
            state.show_energy = !state.show_energy;
            break;
        case GLFW_KEY_SPACE:
            (e.session->playing() ? r.pause : r.play) = true;
            break;
        case GLFW_KEY_M:
            r.tool = ToolKind::MovePins;
            break;
        case GLFW_KEY_D:
            r.tool = ToolKind::AimNormals;
            break;
        case GLFW_KEY_K:
            r.tool = ToolKind::Click;
            break;
        case GLFW_KEY_C:
            if (shift)
                r.create_set = ConstraintKind::Centroid;
            else
                r.tool = ToolKind::Brush;
            break;
        case GLFW_KEY_R:
            if (shift)
                r.create_set = ConstraintKind::Region;
            else
                r.tool = ToolKind::Rectangle;
            break;
        case GLFW_KEY_V:
            r.elements = state.tools.elements == ElementKind::Vertices ? ElementKind::Faces
                                                                       : ElementKind::Vertices;
            break;
        case GLFW_KEY_LEFT_BRACKET:
            state.tools.brush_radius_px = std::max(2.0, state.tools.brush_radius_px / 1.25);
            break;
        case GLFW_KEY_RIGHT_BRACKET:
            state.tools.brush_radius_px = std::min(400.0, state.tools.brush_radius_px * 1.25);
            break;
        case GLFW_KEY_HOME:
        case GLFW_KEY_KP_DECIMAL:
            r.frame_all = true;
            break;
        case GLFW_KEY_F:
            r.frame_selection = true;
            break;
        case GLFW_KEY_KP_1:
        case GLFW_KEY_1:
            r.view = ctrl ? StandardView::Back : StandardView::Front;
            break;
        case GLFW_KEY_KP_3:
        case GLFW_KEY_3:
            r.view = ctrl ? StandardView::Left : StandardView::Right;
            break;
        case GLFW_KEY_KP_7:
        case GLFW_KEY_7:
            r.view = ctrl ? StandardView::Bottom : StandardView::Top;
            break;
        case GLFW_KEY_KP_5:
        case GLFW_KEY_5:
            r.toggle_projection = true;
            break;
        case GLFW_KEY_T:
            state.orbit = state.orbit == OrbitStyle::Turntable ? OrbitStyle::Trackball
                                                               : OrbitStyle::Turntable;
            break;
        case GLFW_KEY_W:
            d.wireframe = !d.wireframe;
            break;
        case GLFW_KEY_B:
            if (ctrl)
                r.command = SelectionCommand::Boundary;
            else
                d.boundary_edges = !d.boundary_edges;
            break;
        case GLFW_KEY_P:
            if (shift)
                r.create_set = ConstraintKind::Pin;
            else
                d.vertex_points = !d.vertex_points;
            break;
        case GLFW_KEY_TAB:
            state.show_side_panel = !state.show_side_panel;
            break;
        case GLFW_KEY_F1:
        case GLFW_KEY_H:
            state.show_help = !state.show_help;
            break;
        case GLFW_KEY_F12:
            r.screenshot = true;
            break;
        default:
            break;
    }
}

void on_mouse_button(GLFWwindow* window, int button, int action, int mods)
{
    Editor& e = editor_of(window);
    const MouseButton b = button == GLFW_MOUSE_BUTTON_LEFT     ? MouseButton::Left
                          : button == GLFW_MOUSE_BUTTON_MIDDLE ? MouseButton::Middle
                                                               : MouseButton::Right;
    double x = 0, y = 0;
    e.cursor(x, y);
    if (action == GLFW_RELEASE)
    {
        e.session->mouse_release(b, x, y);
        return;
    }
    if (ImGui::GetIO().WantCaptureMouse)
        return;
    e.session->mouse_press(
        b, {bool(mods & GLFW_MOD_SHIFT), bool(mods & GLFW_MOD_CONTROL), bool(mods & GLFW_MOD_ALT)},
        x, y);
}

void on_cursor(GLFWwindow* window, double /*x*/, double /*y*/)
{
    Editor& e = editor_of(window);
    double x = 0, y = 0;
    e.cursor(x, y);
    e.session->mouse_move(x, y);
}

void on_scroll(GLFWwindow* window, double /*dx*/, double dy)
{
    Editor& e = editor_of(window);
    if (ImGui::GetIO().WantCaptureMouse)
        return;
    double x = 0, y = 0;
    e.cursor(x, y);
    e.session->scroll(dy, x, y);
}

void on_drop(GLFWwindow* window, int count, const char** paths)
{
    if (count > 0)
        editor_of(window).pending.open_path = std::string(paths[0]);
}

void on_close(GLFWwindow* window)
{
    Editor& e = editor_of(window);
    if (e.session->document().modified)
    {
        glfwSetWindowShouldClose(window, GLFW_FALSE);
        e.ui.ask_to_quit(e.session->document(), e.pending);
    }
}

} // namespace

void run_window(const WindowOptions& options)
{
    // The first document and view are read before any window opens, so that a bad file
    // is reported like the command-line tool reports it.
    auto editor = std::make_unique<Editor>();
    Document document = load_document(options.mesh_path);
    std::optional<Camera> camera;
    if (!options.view_path.empty())
        camera = camera_from_json(io::read_file(options.view_path), options.view_path);
    editor->screenshot_path = options.screenshot_path;

    glfwSetErrorCallback(remember_glfw_error);
    if (!glfwInit())
        throw NoDisplayError("cannot open a window: " + g_glfw_error);
    struct Terminate
    {
        ~Terminate() { glfwTerminate(); }
    } terminate;
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    const std::string title =
        "MeshFair - " + std::filesystem::path(options.mesh_path).filename().string();
    GLFWwindow* window =
        glfwCreateWindow(options.width, options.height, title.c_str(), nullptr, nullptr);
    if (window == nullptr)
        throw RenderError("cannot create an OpenGL 3.3 core window: " + g_glfw_error);
    struct Destroy
    {
        GLFWwindow* w;
        ~Destroy() { glfwDestroyWindow(w); }
    } destroy{window};
    glfwMakeContextCurrent(window);
    glfwSwapInterval(1);
    // The renderer's GL objects go while the context still exists.
    struct ReleaseGl
    {
        Editor& e;
        ~ReleaseGl()
        {
            e.session.reset();
            e.renderer.reset();
        }
    } release_gl{*editor};
    editor->window = window;
    const std::string renderer_name = gl::load_functions(glfw_proc_address);
    glfwSetWindowUserPointer(window, editor.get());
    glfwSetKeyCallback(window, on_key);
    glfwSetMouseButtonCallback(window, on_mouse_button);
    glfwSetCursorPosCallback(window, on_cursor);
    glfwSetScrollCallback(window, on_scroll);
    glfwSetDropCallback(window, on_drop);
    glfwSetWindowCloseCallback(window, on_close);

    InterfaceContext layer;
    // Installed after MeshFair's callbacks, ImGui's chain to them.
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    struct Shutdown
    {
        ~Shutdown() { ImGui_ImplGlfw_Shutdown(); }
    } shutdown;

    editor->renderer = std::make_unique<GlRenderer>();
    editor->session = std::make_unique<EditorSession>(std::move(document), *editor->renderer);
    {
        EditorState& state = editor->session->state();
        state.renderer_name = renderer_name;
        state.display = options.display;
        state.recent = load_recent(recent_files_path());
        remember_recent(state.recent, options.mesh_path);
        save_recent(recent_files_path(), state.recent);
        if (camera)
            editor->session->camera() = *camera;
        if (const std::optional<RecoveryInfo> offer = editor->session->recovery_offer())
            state.recovery_saved_at = offer->saved_at;
    }

    bool first = true;
    using Clock = std::chrono::steady_clock;
    while (!glfwWindowShouldClose(window))
    {
        // While solving, a frame as soon as the display takes one; else sleep until an
        // event, but redraw at least twice a second.
        if (first || editor->session->playing())
            glfwPollEvents();
        else
            glfwWaitEventsTimeout(0.5);
        const auto start = Clock::now(); // the frame's time, not the wait's
        Editor& e = *editor;
        EditorSession& session = *e.session;
        ImGui_ImplGlfw_NewFrame();
        layer.new_frame();
        session.prepare_ui();
        UiRequests r = e.ui.build(session.document(), session.state(), session.camera());
        layer.end_frame();
        int fb_width = 0, fb_height = 0;
        glfwGetFramebufferSize(window, &fb_width, &fb_height);
        session.set_view_rect(EditorUi::view_rect(fb_width, fb_height, session.state()));
        if (first && !camera)
            session.camera().frame(session.document().box, session.aspect());
        // Keys and callbacks of this frame, then the interface's own requests.
        const UiRequests keys = std::exchange(e.pending, UiRequests{});
        e.carry_out(keys);
        e.carry_out(r);
        session.update();
        session.autosave();
        session.draw();
        if (keys.screenshot || r.screenshot)
            e.screenshot(); // the view without the panels
        layer.draw();
        glfwSwapBuffers(window);
        session.state().frame_ms =
            std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        if (first)
        {
            std::printf("meshfair: window open, %dx%d, %s\n", fb_width, fb_height,
                        session.state().renderer_name.c_str());
            std::fflush(stdout);
            first = false;
        }
    }
    editor->session->end_session(); // a clean exit: no recovery to offer next time
}

} // namespace meshfair::app
