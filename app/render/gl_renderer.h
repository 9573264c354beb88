// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <memory>
#include <vector>

#include "app/render/renderer.h"

namespace meshfair::app {

//! \brief The Renderer on OpenGL 3.3 core, for whatever context is current (a GLFW
//! window or an OSMesa buffer): the same shaders and draw calls in both.
//!
//! Buffers: positions, normals and colours (one vertex buffer each), the fan's triangles,
//! the boundary and singular edges (index buffers), and texture buffers read by the
//! shaders: each triangle's face and polygon sides, each face's area vector and selection
//! flag, and the vertex buffers and triangles again, read by the surface's unindexed
//! variants. The wireframe is drawn by the surface's fragments (shaders/mesh.frag); the
//! surface's program is the variant of what a frame shows, made at its first use. Every
//! entry point checks glGetError and throws RenderError naming itself.
class GlRenderer final : public Renderer
{
public:
    //! \pre a context is current and gl::load_functions succeeded for it.
    GlRenderer();
    ~GlRenderer() override;

    void set_mesh(const Mesh& mesh, const MeshDrawData& data) override;
    void update_positions(std::span<const Scalar> positions) override;
    void update_geometry(const DisplayGeometry& geometry) override;
    void set_vertex_colors(std::span<const float> rgb) override;
    void set_selection(std::span<const char> vertices, std::span<const char> faces) override;
    void set_glyphs(std::span<const GlyphGroup> groups) override;
    void draw(const Camera& camera, const DisplayOptions& options, const ViewRect& view) override;
    Image read_pixels(int width, int height) override;
    PickResult pick(const Camera& camera, const ViewRect& view, int x, int y) override;
    Visibility visibility(const Camera& camera, const ViewRect& view) override;

    //! How many GPU buffers were (re)allocated, counted at the one place that allocates them
    //! (for tests: updating positions must not).
    int buffer_allocations() const { return buffer_allocations_; }
    //! How many times the face area vectors went to the GPU (for tests).
    int face_area_uploads() const { return face_area_uploads_; }
    //! The bytes of positions, normals and face area vectors update_geometry sent to the GPU
    //! so far (for tests: a run's frames send only its changing part).
    std::size_t geometry_bytes_uploaded() const { return geometry_bytes_; }
    //! How many draws rasterized the view; the others copied the view drawn last, since
    //! nothing it shows had changed (for tests).
    int view_renders() const { return view_renders_; }

private:
    struct Gl; // the GL objects, defined where GL is included
    //! Rasterizes the view (the surface, edges, points and glyphs) into the bound
    //! framebuffer, `width` x `height` from its corner.
    void render_view(const glm::mat4& view, const glm::mat4& projection, const Camera& camera,
                     const DisplayOptions& options, int width, int height);
    //! Draws the ID buffer of a `width` x `height` view into the pick framebuffer, left bound.
    void render_ids(const Camera& camera, int width, int height);
    //! Re-uploads the positions, normals and face area vectors (unless empty) in place (no
    //! allocation).
    void upload_geometry(std::span<const float> positions, std::span<const float> normals,
                         std::span<const float> face_areas);
    //! Re-uploads the face area vectors in place; they are then those of the positions.
    void upload_face_areas(std::span<const float> face_areas);
    std::unique_ptr<Gl> gl_;
    Mesh connectivity_; // the faces of the mesh set last (positions not kept)
    std::uint32_t vertex_count_ = 0, face_count_ = 0;
    std::vector<Index> vertex_face_offsets_, vertex_faces_; // the faces around each vertex
    int triangle_indices_ = 0, boundary_indices_ = 0, singular_indices_ = 0;
    std::vector<float> positions_, normals_, face_areas_; // staging, sized by set_mesh
    bool has_colors_ = false;
    // Every face a triangle (the triangle drawn is its face); some vertex, some face
    // selected: which surface program a frame takes.
    bool triangles_only_ = false, any_vertex_selected_ = false, any_face_selected_ = false;
    struct GlyphRange
    {
        GlyphGroup::Shape shape;
        std::array<float, 3> color;
        float size_px;
        int first, count; // in points of the glyph buffer
    };
    std::vector<GlyphRange> glyphs_;
    int buffer_allocations_ = 0, face_area_uploads_ = 0;
    // Whether the last draw read the face area vectors (flat-shaded polygons:
    // update_geometry then uploads them), and whether the GPU's area vectors belong to its
    // positions.
    bool flat_drawn_ = false, face_areas_current_ = true;
    // The display run whose frame the GPU's positions and normals are (0: another source),
    // and the bytes update_geometry uploaded.
    std::uint64_t geometry_run_ = 0;
    std::size_t geometry_bytes_ = 0;
    size_t color_bytes_ = 0, glyph_bytes_ = 0; // what the colour and glyph buffers hold
    // Bumped by every change of what the view shows (mesh, positions, colours, selection,
    // glyphs); the view is kept with the version and the parameters it was drawn with.
    std::uint64_t content_version_ = 0;
    struct DrawnView // valid once view_renders_ > 0
    {
        std::uint64_t version = 0;
        DisplayOptions options;
        int width = 0, height = 0;
        glm::dmat4 view{1.0}, projection{1.0};
    };
    DrawnView drawn_;
    int view_renders_ = 0;
};

} // namespace meshfair::app
