// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cstddef>
#include <vector>

#include "app/render/renderer.h"

namespace meshfair::app {

//! \brief A Renderer without GL, for the editor's tests: it records what it is asked to
//! draw (counts of each call, the last selection, glyphs and colours) and answers picking
//! and visibility from the camera with a software depth test (the faces fan-triangulated
//! and rasterized at pixel centres, the nearest face kept per pixel), by the rule the GL
//! renderer's ID buffer follows (Renderer::visibility).
class RecordingRenderer final : public Renderer
{
public:
    void set_mesh(const Mesh& mesh, const MeshDrawData& data) override;
    void update_positions(std::span<const Scalar> positions) override;
    void update_geometry(const DisplayGeometry& geometry) override;
    void set_vertex_colors(std::span<const float> rgb) override;
    void set_selection(std::span<const char> vertices, std::span<const char> faces) override;
    void set_glyphs(std::span<const GlyphGroup> groups) override;
    void draw(const Camera& camera, const DisplayOptions& options, const ViewRect& view) override;
    //! A black image of the size asked for: there are no pixels without GL.
    Image read_pixels(int width, int height) override;
    PickResult pick(const Camera& camera, const ViewRect& view, int x, int y) override;
    Visibility visibility(const Camera& camera, const ViewRect& view) override;

    //! What was asked for so far.
    struct Calls
    {
        std::size_t set_mesh = 0, update_positions = 0, update_geometry = 0, vertex_colors = 0,
                    selection = 0, glyphs = 0, draw = 0, pick = 0, visibility = 0;
    };
    const Calls& calls() const { return calls_; }
    const std::vector<char>& selected_vertices() const { return selected_vertices_; }
    const std::vector<char>& selected_faces() const { return selected_faces_; }
    const std::vector<GlyphGroup>& glyphs() const { return glyphs_; }
    const std::vector<float>& positions() const { return positions_; }
    //! The last per-vertex colours (3 per vertex), as set_vertex_colors gave them.
    const std::vector<float>& vertex_colors() const { return vertex_colors_; }
    const DisplayOptions& last_options() const { return options_; }

private:
    //! The nearest face and its depth at each pixel of a width x height view (-1: none).
    void rasterize(const Camera& camera, int width, int height);
    Calls calls_;
    std::vector<Index> face_offsets_, face_vertices_;
    std::vector<float> positions_, vertex_colors_;
    std::vector<char> selected_vertices_, selected_faces_;
    std::vector<GlyphGroup> glyphs_;
    DisplayOptions options_;
    std::vector<ScreenPoint> projected_;
    std::vector<float> depth_;
    std::vector<Index> face_at_;
    //! The fan triangle kept at each pixel: the offset in face_vertices_ of its second
    //! corner (pick's vertex is the nearest of that triangle's corners, as in the ID buffer).
    std::vector<size_t> triangle_at_;
};

} // namespace meshfair::app
