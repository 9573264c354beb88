// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

// Offscreen frames for the render tests (OSMesa, llvmpipe) and their comparison with
// the golden images of tests/app/render/golden/.

#include <string>
#include <vector>

#include "app/editor/document.h"
#include "app/render/gl_renderer.h"
#include "app/render/image.h"

namespace meshfair::test {

//! A pixel differs from the golden one when a channel differs by more than this...
inline constexpr int kGoldenChannelTolerance = 8;
//! ...and an image fails when more than this fraction of its pixels differ.
inline constexpr double kGoldenPixelFraction = 0.005;

//! The process's offscreen context, made current at `width` x `height`.
void offscreen_context(int width, int height);

//! What a frame draws besides the mesh.
struct FrameExtras
{
    bool ui = false;                    //!< the editor's panels (the camera refitted to its view)
    bool help = false;                  //!< with the help overlay open
    std::vector<float> vertex_colors{}; //!< the colour overlay, 3 #V
    std::vector<char> selected_vertices{}; //!< #V flags (empty: no selection shown)
    std::vector<char> selected_faces{};    //!< #F flags
};

//! One frame of `document`.
app::Image render_frame(const app::Document& document, const app::Camera& camera,
                        const app::DisplayOptions& display, int width, int height,
                        const FrameExtras& extras = {});

//! \brief Compares `image` with tests/app/render/golden/NAME.png (see the tolerances above). On a
//! failure writes NAME-actual.png and NAME-diff.png into the build's render-failures/
//! folder and says so. With MESHFAIR_UPDATE_GOLDEN=1 in the environment it writes the
//! golden instead (tests/app/render/golden/regenerate.sh).
void check_golden(const std::string& name, const app::Image& image);

} // namespace meshfair::test
