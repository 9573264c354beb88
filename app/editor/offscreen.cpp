// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/offscreen.h"

#include <memory>

#include "app/editor/document.h"
#include "app/editor/editor_ui.h"
#include "app/editor/interface_context.h"
#include "app/render/gl_renderer.h"
#include "app/render/osmesa_context.h"
#include "core/io/io.h"

namespace meshfair::app {

void render_screenshot(const ScreenshotRequest& request)
{
    // Everything that can be refused is read before any context exists.
    const Document document = load_document(request.mesh_path);
    Camera camera;
    if (!request.view_path.empty())
        camera = camera_from_json(io::read_file(request.view_path), request.view_path);

    OsmesaContext context(request.width, request.height);
    GlRenderer renderer;
    renderer.set_mesh(document.mesh, document.draw_data);
    ViewRect rect = ViewRect::whole(request.width, request.height);
    std::unique_ptr<InterfaceContext> layer;
    if (request.ui)
    {
        // The panels first: they decide the rectangle left to the view.
        layer = std::make_unique<InterfaceContext>();
        EditorUi ui;
        EditorState state;
        state.display = request.display;
        state.renderer_name = context.renderer_name();
        state.offscreen = true;
        ui.prepare_offscreen(*layer, document, state, camera, request.width, request.height);
        rect = EditorUi::view_rect(request.width, request.height, state);
    }
    if (request.view_path.empty())
        camera.frame(document.box, double(rect.width) / rect.height);
    renderer.draw(camera, request.display, rect);
    if (layer)
        layer->draw();
    write_png(renderer.read_pixels(request.width, request.height), request.screenshot_path);
    if (!request.save_view_path.empty())
        io::write_file_atomically(request.save_view_path, to_json(camera));
}

} // namespace meshfair::app
