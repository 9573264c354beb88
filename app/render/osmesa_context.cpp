// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/render/osmesa_context.h"

#include <GL/osmesa.h>

#include "app/render/gl_loader.h"
#include "app/render/render_error.h"

namespace meshfair::app {

struct OsmesaContext::Handle
{
    OSMesaContext context = nullptr;
};

namespace {

void* osmesa_proc_address(const char* name)
{
    return reinterpret_cast<void*>(OSMesaGetProcAddress(name));
}

} // namespace

OsmesaContext::OsmesaContext(int width, int height) : handle_(std::make_unique<Handle>())
{
    const int attributes[] = {OSMESA_FORMAT,
                              OSMESA_RGBA,
                              OSMESA_DEPTH_BITS,
                              24,
                              OSMESA_STENCIL_BITS,
                              8,
                              OSMESA_PROFILE,
                              OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION,
                              3,
                              OSMESA_CONTEXT_MINOR_VERSION,
                              3,
                              0};
    handle_->context = OSMesaCreateContextAttribs(attributes, nullptr);
    if (handle_->context == nullptr)
        throw RenderError("OSMesa could not create an OpenGL 3.3 core context");
    resize(width, height);
    renderer_ = gl::load_functions(osmesa_proc_address);
}

OsmesaContext::~OsmesaContext()
{
    if (handle_->context != nullptr)
        OSMesaDestroyContext(handle_->context);
}

void OsmesaContext::resize(int width, int height)
{
    if (width <= 0 || height <= 0 || width > 16384 || height > 16384)
        throw RenderError("offscreen size " + std::to_string(width) + "x" + std::to_string(height) +
                          " is outside 1x1 .. 16384x16384");
    width_ = width;
    height_ = height;
    buffer_.assign(size_t{4} * width * height, 0);
    make_current();
}

void OsmesaContext::make_current()
{
    if (!OSMesaMakeCurrent(handle_->context, buffer_.data(), GL_UNSIGNED_BYTE, width_, height_))
        throw RenderError("OSMesaMakeCurrent failed");
}

} // namespace meshfair::app
