// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/offscreen.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>

#include "app/editor/document.h"
#include "app/editor/editor_session.h"
#include "app/editor/editor_ui.h"
#include "app/editor/interface_context.h"
#include "app/editor/script.h"
#include "app/render/gl_renderer.h"
#include "app/render/osmesa_context.h"
#include "core/io/io.h"

namespace meshfair::app {

OffscreenHost::OffscreenHost(EditorSession& session, int width, int height, bool ui)
    : session_(session), width_(width), height_(height)
{
    if (ui)
        layer_ = std::make_unique<InterfaceContext>();
    frame_ = std::make_unique<EditorFrame>(session_, layer_.get());
}

OffscreenHost::~OffscreenHost() = default;

void OffscreenHost::run_frame()
{
    frame_->run({width_, height_, width_, height_}, 1.0 / 60.0);
}

Image OffscreenHost::frame()
{
    run_frame();
    if (layer_)
        run_frame(); // windows that size themselves to their contents settle in the first
    frame_->draw();
    return session_.renderer().read_pixels(width_, height_);
}

void OffscreenHost::screenshot(const std::string& path)
{
    write_png(frame(), path);
}

Image side_by_side(const Image& left, const Image& right)
{
    Image both;
    both.width = left.width + right.width;
    both.height = std::max(left.height, right.height);
    both.rgba.assign(4 * static_cast<size_t>(both.width) * static_cast<size_t>(both.height), 0);
    for (int y = 0; y < both.height; ++y)
    {
        std::uint8_t* row =
            &both.rgba[4 * static_cast<size_t>(y) * static_cast<size_t>(both.width)];
        if (y < left.height)
            std::copy_n(&left.rgba[4 * static_cast<size_t>(y) * static_cast<size_t>(left.width)],
                        4 * static_cast<size_t>(left.width), row);
        if (y < right.height)
            std::copy_n(&right.rgba[4 * static_cast<size_t>(y) * static_cast<size_t>(right.width)],
                        4 * static_cast<size_t>(right.width),
                        row + 4 * static_cast<size_t>(left.width));
    }
    return both;
}

void render_screenshot(const ScreenshotRequest& request)
{
    // Everything that can be refused is read before any context exists.
    Document document = load_document(request.mesh_path);
    std::optional<Camera> camera;
    if (!request.view_path.empty())
        camera =
            camera_from_json(io::read_file(request.view_path), request.view_path, &document.box);
    std::optional<Script> script;
    if (!request.script_path.empty())
        script = read_script(request.script_path);
    std::optional<Document> beside;
    if (!request.beside_path.empty())
        beside = load_document(request.beside_path);

    OsmesaContext context(request.width, request.height);
    // Each session drawn offscreen: the request's display options and the renderer's name.
    const auto offscreen = [&](EditorSession& s) {
        EditorState& state = s.state();
        state.display = request.display;
        state.renderer_name = context.renderer_name();
        state.offscreen = true;
    };
    GlRenderer renderer;
    EditorSession session(std::move(document), renderer);
    offscreen(session);
    if (request.trace)
        session.set_trace(stdout);
    OffscreenHost host(session, request.width, request.height, request.ui);
    host.run_frame();
    if (camera)
        session.camera() = *camera;
    else
        session.camera().frame(session.document().box, session.aspect());
    if (script)
        play_script(*script, session, host);
    if (!beside)
        host.screenshot(request.screenshot_path);
    else
    {
        const Image left = host.frame();
        GlRenderer beside_renderer;
        EditorSession beside_session(std::move(*beside), beside_renderer);
        offscreen(beside_session);
        OffscreenHost beside_host(beside_session, request.width, request.height, false);
        beside_host.run_frame();
        beside_session.camera() = session.camera();
        write_png(side_by_side(left, beside_host.frame()), request.screenshot_path);
        beside_session.end_session();
    }
    session.end_session();
    if (!request.save_view_path.empty())
        io::write_file_atomically(request.save_view_path, to_json(session.camera()));
}

} // namespace meshfair::app
