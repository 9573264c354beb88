// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace meshfair::app {

//! \brief An offscreen OpenGL 3.3 core context (OSMesa, llvmpipe) drawing into memory: no
//! display and no GLFW. Makes itself current and loads the GL function table.
//! Software rendering is deterministic on a given machine with GALLIUM_DRIVER=llvmpipe
//! (docs/editor.md says which settings the golden images use).
class OsmesaContext
{
public:
    //! \throw RenderError when OSMesa cannot give a 3.3 core context.
    OsmesaContext(int width, int height);
    ~OsmesaContext();
    OsmesaContext(const OsmesaContext&) = delete;
    OsmesaContext& operator=(const OsmesaContext&) = delete;

    //! Changes the buffer's size (and makes the context current again).
    void resize(int width, int height);
    void make_current();
    int width() const { return width_; }
    int height() const { return height_; }
    //! GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
    const std::string& renderer_name() const { return renderer_; }

private:
    struct Handle;
    std::unique_ptr<Handle> handle_;
    std::vector<std::uint8_t> buffer_;
    int width_ = 0, height_ = 0;
    std::string renderer_;
};

} // namespace meshfair::app
