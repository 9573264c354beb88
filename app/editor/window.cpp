// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/window.h"
#include "app/editor/user_files.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include "app/editor/document.h"
#include "app/editor/editor_frame.h"
#include "app/editor/editor_session.h"
#include "app/editor/editor_ui.h"
#include "app/editor/input_event.h"
#include "app/editor/interface_context.h"
#include "app/render/gl_loader.h"
#include "app/render/gl_renderer.h"
#include "app/render/render_error.h"
#include "app/tools/navigation.h"
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
    std::unique_ptr<GlRenderer> renderer;
    std::unique_ptr<EditorSession> session; // after the renderer: it draws with it
    std::unique_ptr<EditorFrame> frame;
    std::vector<std::string> dropped; // files dropped on the window, opened next frame
    std::string screenshot_path;
    int screenshots = 0;

    //! The cursor in framebuffer pixels.
    void cursor(double& x, double& y) const
    {
        // Window coordinates to framebuffer pixels (they differ on scaled displays).
        int ww = 0, wh = 0, fw = 0, fh = 0;
        glfwGetWindowSize(window, &ww, &wh);
        glfwGetFramebufferSize(window, &fw, &fh);
        glfwGetCursorPos(window, &x, &y);
        x = x * fw / std::max(ww, 1);
        y = y * fh / std::max(wh, 1);
    }

    void screenshot(const std::string& asked)
    {
        std::string path = asked.empty() ? screenshot_path : asked;
        if (path.empty())
            path = "meshfair-screenshot-" + std::to_string(++screenshots) + ".png";
        const ViewRect& view = session->view_rect();
        EditorState& state = session->state();
        try
        {
            write_png(renderer->read_pixels(view.framebuffer_width, view.framebuffer_height), path);
            state.message = "screenshot " + path;
            state.message_is_error = false;
        }
        catch (const std::exception& e)
        {
            state.message = e.what();
            state.message_is_error = true;
        }
    }
};

// GLFW's key codes are MeshFair's (app/editor/input_event.h).
static_assert(key::Space == GLFW_KEY_SPACE && key::A == GLFW_KEY_A && key::Z == GLFW_KEY_Z &&
              key::Equal == GLFW_KEY_EQUAL && key::Minus == GLFW_KEY_MINUS &&
              key::LeftBracket == GLFW_KEY_LEFT_BRACKET &&
              key::RightBracket == GLFW_KEY_RIGHT_BRACKET && key::Escape == GLFW_KEY_ESCAPE &&
              key::Enter == GLFW_KEY_ENTER && key::Tab == GLFW_KEY_TAB &&
              key::Backspace == GLFW_KEY_BACKSPACE && key::Delete == GLFW_KEY_DELETE &&
              key::Home == GLFW_KEY_HOME && key::End == GLFW_KEY_END && key::F1 == GLFW_KEY_F1 &&
              key::F12 == GLFW_KEY_F12 && key::Keypad0 == GLFW_KEY_KP_0 &&
              key::KeypadDecimal == GLFW_KEY_KP_DECIMAL && key::KeypadAdd == GLFW_KEY_KP_ADD &&
              key::KeypadSubtract == GLFW_KEY_KP_SUBTRACT &&
              key::KeypadEnter == GLFW_KEY_KP_ENTER && key::LeftShift == GLFW_KEY_LEFT_SHIFT &&
              key::RightSuper == GLFW_KEY_RIGHT_SUPER && key::Left == GLFW_KEY_LEFT &&
              key::Up == GLFW_KEY_UP && key::PageDown == GLFW_KEY_PAGE_DOWN);

Editor& editor_of(GLFWwindow* window)
{
    return *static_cast<Editor*>(glfwGetWindowUserPointer(window));
}

Modifiers modifiers(int mods)
{
    return {bool(mods & GLFW_MOD_SHIFT), bool(mods & GLFW_MOD_CONTROL), bool(mods & GLFW_MOD_ALT)};
}

// The callbacks only queue the input: the frame hands it out (app/editor/input_router.h).
void on_key(GLFWwindow* window, int key, int /*scancode*/, int action, int mods)
{
    if (action == GLFW_REPEAT || key < 0)
        return; // ImGui repeats held keys itself; bindings act once per press
    InputEvent e;
    e.type = action == GLFW_PRESS ? InputEvent::Type::KeyPress : InputEvent::Type::KeyRelease;
    e.key = key;
    e.mods = modifiers(mods);
    editor_of(window).frame->input().push(e);
}

void on_char(GLFWwindow* window, unsigned int codepoint)
{
    InputEvent e;
    e.type = InputEvent::Type::Char;
    e.key = static_cast<int>(codepoint);
    editor_of(window).frame->input().push(e);
}

void on_mouse_button(GLFWwindow* window, int button, int action, int mods)
{
    Editor& ed = editor_of(window);
    InputEvent e;
    e.type = action == GLFW_PRESS ? InputEvent::Type::MousePress : InputEvent::Type::MouseRelease;
    e.button = button == GLFW_MOUSE_BUTTON_LEFT     ? MouseButton::Left
               : button == GLFW_MOUSE_BUTTON_MIDDLE ? MouseButton::Middle
                                                    : MouseButton::Right;
    e.mods = modifiers(mods);
    ed.cursor(e.x, e.y);
    ed.frame->input().push(e);
}

void on_cursor(GLFWwindow* window, double /*x*/, double /*y*/)
{
    Editor& ed = editor_of(window);
    InputEvent e;
    e.type = InputEvent::Type::MouseMove;
    ed.cursor(e.x, e.y);
    ed.frame->input().push(e);
}

void on_scroll(GLFWwindow* window, double /*dx*/, double dy)
{
    Editor& ed = editor_of(window);
    InputEvent e;
    e.type = InputEvent::Type::Scroll;
    e.amount = dy;
    ed.cursor(e.x, e.y);
    ed.frame->input().push(e);
}

void on_drop(GLFWwindow* window, int count, const char** paths)
{
    if (count > 0)
        editor_of(window).dropped.emplace_back(paths[0]);
}

void on_close(GLFWwindow* window)
{
    // Closing the window is Quit: it asks first when there are unsaved changes.
    glfwSetWindowShouldClose(window, GLFW_FALSE);
    editor_of(window).session->dispatch(cmd::Quit{});
}

const char* get_clipboard(void* window)
{
    return glfwGetClipboardString(static_cast<GLFWwindow*>(window));
}

void set_clipboard(void* window, const char* text)
{
    glfwSetClipboardString(static_cast<GLFWwindow*>(window), text);
}

// The widgets' rectangles in window pixels, one per line, after a first line "#frame N"
// with the number of the frame that wrote it: rewritten every frame, once it is on the
// screen, so that a driver can tell that frames were drawn since it last looked, that the
// layout it reads has settled, and that what it sees (a screenshot, the title) shows it.
// The second line is the input handled ("#input EVENTS HELD QUEUED MOVES X Y").
void write_widget_map(const std::string& path, const EditorUi& ui, const FrameSize& size,
                      long frame, const InputRouter& input)
{
    const double sx = double(size.window_width) / std::max(size.framebuffer_width, 1);
    const double sy = double(size.window_height) / std::max(size.framebuffer_height, 1);
    // The input handled by this frame: the events routed so far (not the cursor's moves),
    // whether a key or button is still down, and the events still queued; then the cursor's
    // moves routed so far and where the last one put it, in window pixels (a test waits for
    // the pointer to be seen where it moved it before pressing there).
    std::string text = "#frame\t" + std::to_string(frame) + "\n#input\t" +
                       std::to_string(input.routed_count()) + "\t" +
                       (input.anything_held() ? "1" : "0") + "\t" + (input.pending() ? "1" : "0") +
                       "\t" + std::to_string(input.moved_count()) + "\t" +
                       std::to_string(std::lround(input.cursor_x() * sx)) + "\t" +
                       std::to_string(std::lround(input.cursor_y() * sy)) + "\n";
    char line[64];
    for (const std::string& name : ui.widget_names())
    {
        const WidgetRect r = *ui.widget(name);
        std::snprintf(line, sizeof line, "\t%d\t%d\t%d\t%d\n", int(r.x0 * sx), int(r.y0 * sy),
                      int(r.x1 * sx), int(r.y1 * sy));
        text += name + line;
    }
    // Replaced by a rename, so that a reader never sees half a map; not flushed to disk
    // (io::write_file_atomically's two fsyncs every frame would slow the frames the tests
    // drive, for a file nobody needs after a crash). A map for test automation: a failure
    // never stops the editor.
    const std::string next = path + ".next";
    std::ofstream out(next, std::ios::binary | std::ios::trunc);
    out << text;
    out.close();
    std::error_code ignored;
    if (out)
        std::filesystem::rename(next, path, ignored);
}

std::string window_title(const Document& document)
{
    return "MeshFair - " + std::filesystem::path(document.path).filename().string() +
           (document.modified ? " *" : "");
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
        camera =
            camera_from_json(io::read_file(options.view_path), options.view_path, &document.box);
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
    std::string title = window_title(document);
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
    InterfaceContext layer;
    editor->renderer = std::make_unique<GlRenderer>();
    editor->session = std::make_unique<EditorSession>(std::move(document), *editor->renderer);
    editor->frame = std::make_unique<EditorFrame>(*editor->session, &layer);
    {
        ImGuiIO& io = ImGui::GetIO();
        io.ClipboardUserData = window;
        io.GetClipboardTextFn = get_clipboard;
        io.SetClipboardTextFn = set_clipboard;
    }
    glfwSetKeyCallback(window, on_key);
    glfwSetCharCallback(window, on_char);
    glfwSetMouseButtonCallback(window, on_mouse_button);
    glfwSetCursorPosCallback(window, on_cursor);
    glfwSetScrollCallback(window, on_scroll);
    glfwSetDropCallback(window, on_drop);
    glfwSetWindowCloseCallback(window, on_close);
    EditorSession& session = *editor->session;
    if (options.trace)
        session.set_trace(stdout);
    long frames = 0; // drawn so far
    {
        EditorState& state = session.state();
        state.renderer_name = renderer_name;
        state.display = options.display;
        state.recent = load_recent(recent_files_path());
        remember_recent(state.recent, options.mesh_path);
        save_recent(recent_files_path(), state.recent);
        if (camera)
            session.camera() = *camera;
        else if (const std::optional<UpAxis> up = load_up_axis(up_axes_path(), options.mesh_path))
        {
            session.camera().up_axis = *up; // as this file was last seen
            session.camera().set_view(StandardView::Front);
        }
        if (const std::optional<RecoveryInfo> offer = session.recovery_offer())
            state.recovery_saved_at = offer->saved_at;
    }

    bool first = true;
    using Clock = std::chrono::steady_clock;
    auto last = Clock::now();
    while (!session.state().quit)
    {
        // While solving or with input waiting, a frame as soon as the display takes one;
        // else sleep until an event, but redraw at least twice a second.
        if (first || session.playing() || editor->frame->input().pending())
            glfwPollEvents();
        else
            glfwWaitEventsTimeout(0.5);
        const auto start = Clock::now(); // the frame's time, not the wait's
        FrameSize size;
        glfwGetFramebufferSize(window, &size.framebuffer_width, &size.framebuffer_height);
        glfwGetWindowSize(window, &size.window_width, &size.window_height);
        editor->frame->run(size, std::chrono::duration<double>(start - last).count());
        last = start;
        if (first && !camera)
            session.camera().frame(session.document().box, session.aspect());
        for (const std::string& path : std::exchange(editor->dropped, {}))
            session.dispatch(cmd::OpenMesh{path});
        session.autosave();
        session.draw();
        if (std::optional<std::string> shot = std::exchange(session.state().screenshot, {}))
            editor->screenshot(*shot); // the view without the panels
        layer.draw();
        glfwSwapBuffers(window);
        if (const std::string now = window_title(session.document()); now != title)
        {
            title = now;
            glfwSetWindowTitle(window, title.c_str());
        }
        // After the swap and the title: a frame in the map is one on the screen.
        if (!options.widget_map.empty())
            write_widget_map(options.widget_map, editor->frame->ui(), size, ++frames,
                             editor->frame->input());
        session.state().frame_ms =
            std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        if (first)
        {
            std::printf("meshfair: window open, %dx%d, %s\n", size.framebuffer_width,
                        size.framebuffer_height, session.state().renderer_name.c_str());
            std::fflush(stdout);
            first = false;
        }
    }
    session.end_session(); // a clean exit: no recovery to offer next time
}

} // namespace meshfair::app
