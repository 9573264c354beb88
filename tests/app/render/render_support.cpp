// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "tests/app/render/render_support.h"

#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <utility>

#include "app/editor/editor_ui.h"
#include "app/editor/history.h"
#include "app/editor/interface_context.h"
#include "app/render/osmesa_context.h"

namespace meshfair::test {

namespace fs = std::filesystem;

void offscreen_context(int width, int height)
{
    // Destroyed by an exit handler registered after the context is made, so that it runs
    // before Mesa's own (registered while the context is made, which stops Mesa's work
    // queues): destroyed after those, the context can wait forever for a job of a stopped
    // queue (a shader cache write), which under load hung 2 in 30 runs of a test that
    // compiles many renderers.
    static app::OsmesaContext* context = nullptr;
    if (!context)
    {
        context = new app::OsmesaContext(width, height);
        std::atexit([] { delete std::exchange(context, nullptr); });
    }
    else if (context->width() != width || context->height() != height)
        context->resize(width, height);
    else
        context->make_current();
}

app::Image render_frame(const app::Document& document, const app::Camera& camera,
                        const app::DisplayOptions& display, int width, int height,
                        const FrameExtras& extras)
{
    offscreen_context(width, height);
    app::GlRenderer renderer;
    renderer.set_mesh(document.mesh, document.draw_data);
    if (!extras.vertex_colors.empty())
        renderer.set_vertex_colors(extras.vertex_colors);
    if (!extras.selected_vertices.empty())
        renderer.set_selection(extras.selected_vertices, extras.selected_faces);
    if (!extras.ui)
    {
        renderer.draw(camera, display, app::ViewRect::whole(width, height));
        return renderer.read_pixels(width, height);
    }
    app::InterfaceContext layer;
    app::EditorUi editor;
    app::EditorState state;
    state.display = display;
    state.renderer_name = "llvmpipe"; // not the LLVM version: the golden must not depend on it
    state.offscreen = true;
    state.show_help = extras.help;
    state.history.limit = app::History().limit(); // what a session shows before any step
    editor.prepare_offscreen(layer, document, state, camera, width, height);
    const app::ViewRect rect = app::EditorUi::view_rect(width, height, state);
    app::Camera fitted = camera;
    fitted.frame(document.box, double(rect.width) / rect.height);
    renderer.draw(fitted, display, rect);
    layer.draw();
    return renderer.read_pixels(width, height);
}

void check_golden(const std::string& name, const app::Image& image)
{
    const fs::path golden = fs::path(MESHFAIR_GOLDEN_DIR) / (name + ".png");
    const char* update = std::getenv("MESHFAIR_UPDATE_GOLDEN");
    if (update != nullptr && std::string(update) == "1")
    {
        app::write_png(image, golden.string());
        MESSAGE("wrote " << golden.string());
        return;
    }
    REQUIRE_MESSAGE(fs::exists(golden), "no golden image " << golden.string());
    const app::Image expected = app::read_png(golden.string());
    const app::ImageDifference d = app::compare_images(image, expected, kGoldenChannelTolerance);
    const bool ok = d.same_size && d.fraction_over_tolerance <= kGoldenPixelFraction;
    if (!ok)
    {
        const fs::path out = fs::path(MESHFAIR_RENDER_FAILURES_DIR);
        fs::create_directories(out);
        app::write_png(image, (out / (name + "-actual.png")).string());
        app::write_png(app::difference_image(image, expected, kGoldenChannelTolerance),
                       (out / (name + "-diff.png")).string());
        MESSAGE("actual and difference images written to " << out.string());
    }
    CHECK_MESSAGE(d.same_size, name << ": " << image.width << "x" << image.height << " against "
                                    << expected.width << "x" << expected.height);
    CHECK_MESSAGE(d.fraction_over_tolerance <= kGoldenPixelFraction,
                  name << ": " << d.pixels_over_tolerance << " pixels ("
                       << 100 * d.fraction_over_tolerance << " %) differ by more than "
                       << kGoldenChannelTolerance << " (largest difference "
                       << d.max_channel_difference << ")");
}

} // namespace meshfair::test
