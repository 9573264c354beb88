// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "app/render/camera.h"
#include "app/render/image.h"
#include "app/render/mesh_draw_data.h"
#include "core/mesh/mesh.h"
#include "core/select/screen_select.h"

namespace meshfair::app {

enum class Shading
{
    Flat,  //!< one normal per polygon (its area vector)
    Smooth //!< area-weighted vertex normals, interpolated
};

//! What a frame shows besides the surface; every flag is independent.
struct DisplayOptions
{
    Shading shading = Shading::Smooth;
    bool wireframe = false;     //!< the polygon edges (never the fan's diagonals)
    bool boundary_edges = true; //!< boundary edges in orange, singular edges in magenta
    bool vertex_points = false; //!< a dot on every vertex
    bool back_face_tint = true; //!< back faces drawn bluish, so holes and flips show
    bool vertex_colors = false; //!< the per-vertex colour overlay (set_vertex_colors)
    std::array<float, 3> surface_color{0.80f, 0.78f, 0.72f};
    std::array<float, 3> background{0.17f, 0.18f, 0.20f};
    float edge_width_px = 1.0f;
    float point_size_px = 4.0f;

    bool operator==(const DisplayOptions&) const = default;
};

//! \brief Where the 3D view lies in the framebuffer: a rectangle in pixels, (x, y) its
//! top-left corner, inside a framebuffer of the given size (the interface's panels take
//! the rest). The camera's width and height are the view's.
struct ViewRect
{
    int framebuffer_width = 0;
    int framebuffer_height = 0;
    int x = 0, y = 0, width = 0, height = 0;

    //! The whole framebuffer.
    static ViewRect whole(int width, int height) { return {width, height, 0, 0, width, height}; }
};

//! What is under a pixel: the face, the nearest of the drawn triangle's corners on
//! screen, and the surface point; hit is false on the background.
struct PickResult
{
    bool hit = false;
    Index face = kInvalidIndex;
    Index vertex = kInvalidIndex;
    glm::dvec3 point{0.0};
};

//! \brief What a view shows, for the selection tools' "front-facing only": every vertex
//! projected into the view's pixels, and flags of the vertices and faces not hidden.
struct Visibility
{
    std::vector<ScreenPoint> projected; //!< one per vertex, in the view's pixels
    std::vector<char> vertices;         //!< 1: in the view and not behind the surface
    std::vector<char> faces;            //!< 1: covers at least one pixel of the view
};

//! How much farther than the surface drawn around it (in window depth) a vertex may lie
//! and still count as visible: the depth buffer's resolution.
inline constexpr double kVisibilityDepthMargin = 2e-4;

//! \brief Markers drawn over the surface, one colour per group: the constraint sets'
//! glyphs (pins, anchors, centroids, normal arrows, a region's border ring). Hidden by
//! the surface in front of them, like the vertices.
struct GlyphGroup
{
    enum class Shape
    {
        Dots,    //!< a round dot of size_px at each point (3 floats each)
        Segments //!< a line of size_px width between each pair of points (6 floats each)
    };
    Shape shape = Shape::Dots;
    std::vector<float> points;
    std::array<float, 3> color{1, 1, 1};
    float size_px = 6;
};

//! \brief The viewer's drawing interface, free of GL types: the same calls draw in a
//! window, into an OSMesa buffer or into a recording for tests.
//!
//! set_mesh is for a new connectivity and rebuilds every buffer; update_positions is for
//! new positions of the same connectivity and re-uploads only the positions and normals
//! (no shader is rebuilt, no buffer reallocated).
class Renderer
{
public:
    virtual ~Renderer() = default;
    virtual void set_mesh(const Mesh& mesh, const MeshDrawData& data) = 0;
    //! \pre positions has 3 #V entries of the mesh last given to set_mesh.
    virtual void update_positions(std::span<const Scalar> positions) = 0;
    //! \brief New positions with their normals already computed (by the solver's thread):
    //! floats, 3 #V positions and vertex normals and 3 #F face area vectors. Uploads only
    //! (the area vectors only while flat shading shows them), and when the geometry shown is
    //! a frame of the same run (nothing else given since), only the run's changing part.
    virtual void update_geometry(const DisplayGeometry& geometry) = 0;
    //! RGB in [0, 1], 3 #V floats; empty clears the overlay.
    virtual void set_vertex_colors(std::span<const float> rgb) = 0;
    //! \brief Shows a selection: selected faces and the surface around selected vertices
    //! tinted in the selection's colour (palette::kSelection); one flag per vertex and per
    //! face (all 0 hides it).
    virtual void set_selection(std::span<const char> vertices, std::span<const char> faces) = 0;
    //! Replaces the glyphs drawn over the surface (none: empty).
    virtual void set_glyphs(std::span<const GlyphGroup> groups) = 0;
    //! Clears the current framebuffer and draws the mesh into the view's rectangle.
    virtual void draw(const Camera& camera, const DisplayOptions& options,
                      const ViewRect& view) = 0;
    //! The current framebuffer's pixels, top row first.
    virtual Image read_pixels(int width, int height) = 0;
    //! \brief Renders the ID buffer (face and nearest vertex per pixel) of the view on
    //! demand and reads pixel (x, y) of the view, (0, 0) being its top-left one.
    virtual PickResult pick(const Camera& camera, const ViewRect& view, int x, int y) = 0;
    //! \brief Renders the ID buffer on demand and tells which vertices and faces it shows.
    virtual Visibility visibility(const Camera& camera, const ViewRect& view) = 0;
};

} // namespace meshfair::app
