// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/render/gl_renderer.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <string>

#include <glm/gtc/type_ptr.hpp>

#include "app/render/gl_functions.h"
#include "app/render/gl_program.h"
#include "app/render/palette.h"
#include "app/render/render_error.h"
#include "core/parallel/parallel.h"

namespace meshfair::app {

namespace {

void check(const char* where)
{
    const GLenum error = glGetError();
    if (error == GL_NO_ERROR)
        return;
    char hex[16];
    std::snprintf(hex, sizeof hex, "0x%04x", error);
    throw RenderError(std::string("OpenGL error ") + hex + " in GlRenderer::" + where);
}

enum Attribute : GLuint
{
    kPosition = 0,
    kNormal = 1,
    kColor = 2,
    kSelected = 3
};

// Every buffer allocation goes through here, and is counted.
template <class T>
void upload(GLenum target, GLuint buffer, std::span<const T> data, int& allocations)
{
    ++allocations;
    glBindBuffer(target, buffer);
    glBufferData(target, static_cast<GLsizeiptr>(data.size() * sizeof(T)),
                 data.empty() ? nullptr : data.data(), GL_DYNAMIC_DRAW);
}

// Data that changes every frame (glyphs, heat-map colours) of a size that rarely does:
// rewritten in place, reallocated (and counted) only when its size changes.
template <class T>
void update(GLenum target, GLuint buffer, std::span<const T> data, size_t& bytes, int& allocations)
{
    if (data.size_bytes() != bytes)
    {
        upload<T>(target, buffer, data, allocations);
        bytes = data.size_bytes();
        return;
    }
    glBindBuffer(target, buffer);
    if (bytes > 0)
        glBufferSubData(target, 0, static_cast<GLsizeiptr>(bytes), data.data());
}

void set_matrices(const gl::Program& p, const glm::mat4& view, const glm::mat4& projection)
{
    glUniformMatrix4fv(p["u_view"], 1, GL_FALSE, glm::value_ptr(view));
    glUniformMatrix4fv(p["u_projection"], 1, GL_FALSE, glm::value_ptr(projection));
}

// A framebuffer of a colour and a 24-bit depth renderbuffer, (re)made at the size asked
// for: the ID buffer's, and the kept view's.
struct RenderTarget
{
    GLenum color_format;
    const char* name; // for the error
    GLuint framebuffer = 0, color = 0, depth = 0;
    int width = 0, height = 0;

    RenderTarget(GLenum format, const char* what) : color_format(format), name(what) {}
    RenderTarget(const RenderTarget&) = delete;
    RenderTarget& operator=(const RenderTarget&) = delete;
    ~RenderTarget()
    {
        glDeleteFramebuffers(1, &framebuffer);
        glDeleteRenderbuffers(1, &color);
        glDeleteRenderbuffers(1, &depth);
    }

    //! Sized `w` x `h` and bound (GL_FRAMEBUFFER).
    void prepare(int w, int h)
    {
        if (framebuffer != 0 && w == width && h == height)
        {
            glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
            return;
        }
        if (framebuffer == 0)
        {
            glGenFramebuffers(1, &framebuffer);
            glGenRenderbuffers(1, &color);
            glGenRenderbuffers(1, &depth);
        }
        glBindRenderbuffer(GL_RENDERBUFFER, color);
        glRenderbufferStorage(GL_RENDERBUFFER, color_format, w, h);
        glBindRenderbuffer(GL_RENDERBUFFER, depth);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, w, h);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
        if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw RenderError(std::string("the ") + name + "'s framebuffer is incomplete");
        width = w;
        height = h;
    }
};

// The surface program's variants (shaders/mesh.frag): each reads and interpolates only
// what the frame shows. On llvmpipe every vertex output costs every vertex and triangle,
// and reading gl_PrimitiveID makes it copy each triangle's vertices apart (at 1.25 M
// vertices the two together doubled a frame); a GPU minds neither.
enum SurfaceVariant : unsigned
{
    kFlat = 1,            // flat shading
    kTrianglesOnly = 2,   // every face a triangle: the triangle drawn is its face
    kVertexColors = 4,    // the per-vertex colour overlay
    kVertexSelection = 8, // some vertex selected (the tint around it)
    kFaceSelection = 16,  // some face selected
    kWireframe = 32,      // the polygon edges, drawn by the surface's fragments
    kTriangleId = 64      // unindexed triangles, each fragment knowing its own
};

//! Whether a variant's fragments need their triangle: its face's flag, the polygon's area
//! vector, the corners of the wireframe.
unsigned with_triangle_id(unsigned variant)
{
    const bool needs = (variant & (kWireframe | kFaceSelection)) != 0 ||
                       ((variant & kFlat) != 0 && (variant & kTrianglesOnly) == 0);
    return needs ? variant | kTriangleId : variant;
}

std::unique_ptr<gl::Program> surface_program(unsigned variant)
{
    std::string defines;
    std::vector<const char*> uniforms{"u_view", "u_projection", "u_back_tint", "u_eye_ray",
                                      "u_back_face_color"};
    const bool polygons = (variant & kTrianglesOnly) == 0;
    const auto define = [&](unsigned bit, const char* name) {
        if (variant & bit)
            defines += std::string("#define ") + name + "\n";
    };
    define(kFlat, "FLAT");
    define(kTrianglesOnly, "TRIANGLES");
    define(kVertexColors, "VERTEX_COLORS");
    define(kVertexSelection, "VERTEX_SELECTION");
    define(kFaceSelection, "FACE_SELECTION");
    define(kWireframe, "WIREFRAME");
    define(kTriangleId, "TRIANGLE_ID");
    if (!(variant & kVertexColors))
        uniforms.push_back("u_surface_color");
    if (variant & (kVertexSelection | kFaceSelection))
        uniforms.push_back("u_selection_color");
    if (polygons && (variant & (kFlat | kFaceSelection)))
        uniforms.push_back("u_triangle_face");
    if (polygons && (variant & kFlat))
        uniforms.push_back("u_face_area");
    if (variant & kFaceSelection)
        uniforms.push_back("u_face_selected");
    if (variant & kWireframe)
        for (const char* u : {"u_edge_width_px", "u_edge_color"})
            uniforms.push_back(u);
    if (polygons && (variant & kWireframe))
        uniforms.push_back("u_triangle_edges");
    if (variant & kTriangleId)
    {
        uniforms.push_back("u_triangle_corners");
        uniforms.push_back("u_positions");
        if (!(variant & kFlat))
            uniforms.push_back("u_normals");
        if (variant & kVertexColors)
            uniforms.push_back("u_colors");
        if (variant & kVertexSelection)
            uniforms.push_back("u_vertex_selected");
    }
    return std::make_unique<gl::Program>("mesh", false, uniforms, defines);
}

// Texture units of the buffers the surface's and the ID buffer's shaders read.
enum TextureUnit : GLint
{
    kTriangleFaceUnit = 0,
    kFaceAreaUnit = 1,
    kFaceSelectedUnit = 2,
    kTriangleCornersUnit = 3,
    kPositionsUnit = 4,
    kNormalsUnit = 5,
    kColorsUnit = 6,
    kVertexSelectedUnit = 7,
    kTriangleEdgesUnit = 8
};

} // namespace

struct GlRenderer::Gl
{
    // The surface's programs, made when a frame first needs them (by SurfaceVariant bits).
    std::map<unsigned, std::unique_ptr<gl::Program>> surface;
    gl::Program lines{
        "lines",
        true,
        {"u_view", "u_projection", "u_viewport_px", "u_width_px", "u_depth_bias", "u_color"}};
    gl::Program points{
        "points",
        true,
        {"u_view", "u_projection", "u_viewport_px", "u_size_px", "u_depth_bias", "u_color"}};
    gl::Program ids{"pick", true, {"u_view", "u_projection", "u_triangle_face", "u_viewport_px"}};
    GLuint surface_vao = 0, lines_vao = 0;
    GLuint positions = 0, normals = 0, colors = 0, triangles = 0;
    GLuint boundary = 0, singular = 0;
    GLuint triangle_face = 0, face_area = 0; // buffers behind the textures
    GLuint triangle_face_texture = 0, face_area_texture = 0;
    // The unindexed surface's (TRIANGLE_ID): no vertex arrays, the index buffer a corner a
    // texel, the vertices' attributes, and for the wireframe which sides of each triangle
    // are polygon edges (one byte a triangle).
    GLuint pulled_vao = 0, triangle_corners_texture = 0, positions_texture = 0;
    GLuint normals_texture = 0, colors_texture = 0, vertex_selected_texture = 0;
    GLuint triangle_edges = 0, triangle_edges_texture = 0;
    GLuint face_selected = 0, face_selected_texture = 0; // one byte per face
    GLuint selected_points = 0;                          // indices of the selected vertices
    GLuint vertex_selected = 0;                          // one byte per vertex (the tint)
    GLuint glyph_vao = 0, glyph_points = 0;              // the glyphs' points, all groups
    GLsizei selected_point_count = 0;
    RenderTarget pick{GL_RG32UI, "ID buffer"}; // face and vertex ids, 1-based
    // The 3D view, kept between frames: 8-bit RGBA and a 24-bit depth, as the windows and
    // OSMesa buffers it is copied to, so that what is drawn there is what drawing directly
    // drew.
    RenderTarget view{GL_RGBA8, "view"};

    Gl()
    {
        glGenVertexArrays(1, &surface_vao);
        glGenVertexArrays(1, &lines_vao);
        GLuint* buffers[] = {&positions, &normals,  &colors,        &triangles,
                             &boundary,  &singular, &triangle_face, &face_area};
        for (GLuint* b : buffers)
            glGenBuffers(1, b);
        glGenBuffers(1, &face_selected);
        glGenBuffers(1, &triangle_edges);
        glGenBuffers(1, &selected_points);
        glGenBuffers(1, &vertex_selected);
        glGenVertexArrays(1, &glyph_vao);
        glGenBuffers(1, &glyph_points);
        glBindVertexArray(glyph_vao);
        glBindBuffer(GL_ARRAY_BUFFER, glyph_points);
        glVertexAttribPointer(kPosition, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
        glEnableVertexAttribArray(kPosition);
        glBindVertexArray(0);
        for (GLuint* t : {&triangle_face_texture, &face_area_texture, &face_selected_texture,
                          &triangle_edges_texture, &positions_texture, &triangle_corners_texture,
                          &normals_texture, &colors_texture, &vertex_selected_texture})
            glGenTextures(1, t);
        glGenVertexArrays(1, &pulled_vao);
        glBindVertexArray(surface_vao);
        glBindBuffer(GL_ARRAY_BUFFER, positions);
        glVertexAttribPointer(kPosition, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
        glEnableVertexAttribArray(kPosition);
        glBindBuffer(GL_ARRAY_BUFFER, normals);
        glVertexAttribPointer(kNormal, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
        glEnableVertexAttribArray(kNormal);
        glBindBuffer(GL_ARRAY_BUFFER, colors);
        glVertexAttribPointer(kColor, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
        glBindBuffer(GL_ARRAY_BUFFER, vertex_selected);
        // The flags as they are, 0 or 1, read as floats (not normalized: 1 is 1.0).
        glVertexAttribPointer(kSelected, 1, GL_UNSIGNED_BYTE, GL_FALSE, 0, nullptr);
        glEnableVertexAttribArray(kSelected);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, triangles);
        glBindVertexArray(lines_vao);
        glBindBuffer(GL_ARRAY_BUFFER, positions);
        glVertexAttribPointer(kPosition, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
        glEnableVertexAttribArray(kPosition);
        glBindVertexArray(0);
        // A buffer name exists only once bound; the textures need existing buffers.
        for (GLuint b : {triangle_face, face_area, face_selected, boundary, singular,
                         selected_points, triangle_edges})
            glBindBuffer(GL_TEXTURE_BUFFER, b);
        glBindBuffer(GL_TEXTURE_BUFFER, 0);
        // Each texture views its buffer as the shaders read it.
        const struct
        {
            GLuint texture;
            GLenum format;
            GLuint buffer;
        } views[] = {{triangle_face_texture, GL_R32UI, triangle_face},
                     {face_area_texture, GL_RGB32F, face_area},
                     {face_selected_texture, GL_R8UI, face_selected},
                     {triangle_edges_texture, GL_R8UI, triangle_edges},
                     {positions_texture, GL_RGB32F, positions},
                     {triangle_corners_texture, GL_R32UI, triangles},
                     {normals_texture, GL_RGB32F, normals},
                     {colors_texture, GL_RGB32F, colors},
                     {vertex_selected_texture, GL_R8UI, vertex_selected}};
        for (const auto& v : views)
        {
            glBindTexture(GL_TEXTURE_BUFFER, v.texture);
            glTexBuffer(GL_TEXTURE_BUFFER, v.format, v.buffer);
        }
        glBindTexture(GL_TEXTURE_BUFFER, 0);
    }

    ~Gl()
    {
        glDeleteVertexArrays(1, &surface_vao);
        glDeleteVertexArrays(1, &lines_vao);
        const GLuint buffers[] = {positions, normals,  colors,        triangles,
                                  boundary,  singular, triangle_face, face_area};
        glDeleteBuffers(8, buffers);
        glDeleteBuffers(1, &face_selected);
        glDeleteBuffers(1, &triangle_edges);
        glDeleteBuffers(1, &selected_points);
        glDeleteBuffers(1, &vertex_selected);
        glDeleteVertexArrays(1, &glyph_vao);
        glDeleteBuffers(1, &glyph_points);
        glDeleteTextures(1, &triangle_face_texture);
        glDeleteTextures(1, &face_area_texture);
        glDeleteTextures(1, &face_selected_texture);
        glDeleteTextures(1, &triangle_edges_texture);
        glDeleteTextures(1, &positions_texture);
        for (GLuint t :
             {triangle_corners_texture, normals_texture, colors_texture, vertex_selected_texture})
            glDeleteTextures(1, &t);
        glDeleteVertexArrays(1, &pulled_vao);
    }

    void bind_face_textures() const
    {
        const std::pair<TextureUnit, GLuint> textures[] = {
            {kTriangleFaceUnit, triangle_face_texture},
            {kFaceAreaUnit, face_area_texture},
            {kFaceSelectedUnit, face_selected_texture},
            {kPositionsUnit, positions_texture},
            {kTriangleEdgesUnit, triangle_edges_texture},
            {kNormalsUnit, normals_texture},
            {kColorsUnit, colors_texture},
            {kVertexSelectedUnit, vertex_selected_texture},
            {kTriangleCornersUnit, triangle_corners_texture}};
        for (const auto& [unit, texture] : textures)
        {
            glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
            glBindTexture(GL_TEXTURE_BUFFER, texture);
        }
        glActiveTexture(GL_TEXTURE0);
    }

    //! The surface's program of `variant`, made at its first use.
    const gl::Program& surface_variant(unsigned variant)
    {
        std::unique_ptr<gl::Program>& p = surface[variant];
        if (!p)
            p = surface_program(variant);
        return *p;
    }
};

GlRenderer::GlRenderer() : gl_(std::make_unique<Gl>())
{
    check("GlRenderer");
}

GlRenderer::~GlRenderer() = default;

void GlRenderer::set_mesh(const Mesh& mesh, const MeshDrawData& data)
{
    ++content_version_; // the view drawn last no longer shows it
    connectivity_.positions.clear();
    connectivity_.face_offsets = mesh.face_offsets;
    connectivity_.face_vertices = mesh.face_vertices;
    // After the upload the renderer needs the counts and the faces around each vertex
    // (for the normals), not the index lists, which live in GPU buffers.
    vertex_count_ = data.vertex_count;
    face_count_ = data.face_count;
    vertex_face_offsets_ = data.vertex_face_offsets;
    vertex_faces_ = data.vertex_faces;
    triangle_indices_ = static_cast<GLsizei>(data.triangles.size());
    boundary_indices_ = static_cast<GLsizei>(data.boundary_edges.size());
    singular_indices_ = static_cast<GLsizei>(data.singular_edges.size());
    positions_.assign(3 * static_cast<size_t>(mesh.vertex_count()), 0.0f);
    normals_.assign(positions_.size(), 0.0f);
    face_areas_.assign(3 * static_cast<size_t>(mesh.face_count()), 0.0f);
    int& n = buffer_allocations_;
    upload<float>(GL_ARRAY_BUFFER, gl_->positions, positions_, n);
    upload<float>(GL_ARRAY_BUFFER, gl_->normals, normals_, n);
    upload<float>(GL_TEXTURE_BUFFER, gl_->face_area, face_areas_, n);
    upload<std::uint32_t>(GL_TEXTURE_BUFFER, gl_->triangle_face, data.triangle_face, n);
    upload<std::uint8_t>(GL_TEXTURE_BUFFER, gl_->triangle_edges, data.triangle_edges, n);
    // A mesh of triangles only: each triangle drawn is its face, and all its sides edges.
    triangles_only_ = data.triangle_face.size() == face_count_;
    for (size_t t = 0; triangles_only_ && t < data.triangle_face.size(); ++t)
        triangles_only_ = data.triangle_face[t] == t;
    any_vertex_selected_ = any_face_selected_ = false;
    upload<std::uint8_t>(GL_TEXTURE_BUFFER, gl_->face_selected,
                         std::vector<std::uint8_t>(static_cast<size_t>(face_count_), 0), n);
    gl_->selected_point_count = 0;
    upload<std::uint8_t>(GL_ARRAY_BUFFER, gl_->vertex_selected,
                         std::vector<std::uint8_t>(static_cast<size_t>(vertex_count_), 0), n);
    upload<std::uint32_t>(GL_ELEMENT_ARRAY_BUFFER, gl_->boundary, data.boundary_edges, n);
    upload<std::uint32_t>(GL_ELEMENT_ARRAY_BUFFER, gl_->singular, data.singular_edges, n);
    // The triangles' index buffer belongs to the surface's vertex array.
    glBindVertexArray(gl_->surface_vao);
    upload<std::uint32_t>(GL_ELEMENT_ARRAY_BUFFER, gl_->triangles, data.triangles, n);
    glBindVertexArray(0);
    has_colors_ = false;
    update_positions(mesh.positions);
    check("set_mesh");
}

void GlRenderer::update_positions(std::span<const Scalar> positions)
{
    ++content_version_; // the view drawn last no longer shows it
    geometry_run_ = 0;  // not a solver frame
    if (positions.size() != positions_.size())
        throw RenderError("GlRenderer::update_positions: " + std::to_string(positions.size()) +
                          " coordinates for a mesh of " + std::to_string(positions_.size()));
    positions_to_float(positions, positions_);
    face_area_vectors(positions, connectivity_, face_areas_);
    vertex_normals(vertex_face_offsets_, vertex_faces_, face_areas_, normals_);
    upload_geometry(positions_, normals_, face_areas_);
    check("update_positions");
}

void GlRenderer::update_geometry(const DisplayGeometry& g)
{
    ++content_version_; // the view drawn last no longer shows it
    if (g.positions.size() != positions_.size() || g.normals.size() != normals_.size() ||
        g.face_areas.size() != face_areas_.size())
        throw RenderError("GlRenderer::update_geometry: " + std::to_string(g.positions.size()) +
                          " coordinates, " + std::to_string(g.normals.size()) + " normal and " +
                          std::to_string(g.face_areas.size()) + " face values for a mesh of " +
                          std::to_string(positions_.size() / 3) + " vertices and " +
                          std::to_string(face_areas_.size() / 3) + " faces");
    // The positions are kept for visibility(); the GPU gets the arrays as given, the face
    // area vectors only while flat shading reads them (they are half the bytes of a frame's
    // upload): else draw() brings them up to date when flat shading is turned on.
    if (g.run == 0 || g.run != geometry_run_ || g.changing == nullptr)
    {
        std::copy(g.positions.begin(), g.positions.end(), positions_.begin());
        face_areas_current_ = false; // until uploaded with these positions
        upload_geometry(
            positions_, g.normals,
            flat_drawn_ ? std::span<const float>(g.face_areas) : std::span<const float>{});
        geometry_bytes_ +=
            (g.positions.size() + g.normals.size() + (flat_drawn_ ? g.face_areas.size() : 0)) *
            sizeof(float);
    }
    else
    {
        // A frame of the run shown: only its changing part differs from what the GPU has.
        const auto upload_ranges = [&](GLenum target, GLuint buffer, const IndexRanges& r,
                                       std::span<const float> values) {
            glBindBuffer(target, buffer);
            for (size_t k = 0; k < r.begin.size(); ++k)
            {
                const size_t first = 3 * static_cast<size_t>(r.begin[k]);
                const size_t count = 3 * static_cast<size_t>(r.end[k] - r.begin[k]);
                glBufferSubData(target, static_cast<GLintptr>(first * sizeof(float)),
                                static_cast<GLsizeiptr>(count * sizeof(float)),
                                values.data() + first);
                geometry_bytes_ += count * sizeof(float);
            }
        };
        const IndexRanges& vertices = g.changing->vertices;
        for (size_t k = 0; k < vertices.begin.size(); ++k)
            std::copy(g.positions.begin() + 3 * static_cast<std::ptrdiff_t>(vertices.begin[k]),
                      g.positions.begin() + 3 * static_cast<std::ptrdiff_t>(vertices.end[k]),
                      positions_.begin() + 3 * static_cast<std::ptrdiff_t>(vertices.begin[k]));
        upload_ranges(GL_ARRAY_BUFFER, gl_->positions, vertices, positions_);
        upload_ranges(GL_ARRAY_BUFFER, gl_->normals, vertices, g.normals);
        if (flat_drawn_ && face_areas_current_)
        {
            upload_ranges(GL_TEXTURE_BUFFER, gl_->face_area, g.changing->faces, g.face_areas);
            ++face_area_uploads_;
        }
        else if (flat_drawn_)
        {
            upload_face_areas(g.face_areas);
            geometry_bytes_ += g.face_areas.size() * sizeof(float);
        }
        else
            face_areas_current_ = false;
    }
    geometry_run_ = g.run;
    check("update_geometry");
}

void GlRenderer::upload_geometry(std::span<const float> positions, std::span<const float> normals,
                                 std::span<const float> face_areas)
{
    const auto sub = [](GLenum target, GLuint buffer, std::span<const float> v) {
        glBindBuffer(target, buffer);
        glBufferSubData(target, 0, static_cast<GLsizeiptr>(v.size() * sizeof(float)), v.data());
    };
    sub(GL_ARRAY_BUFFER, gl_->positions, positions);
    sub(GL_ARRAY_BUFFER, gl_->normals, normals);
    if (!face_areas.empty())
        upload_face_areas(face_areas);
}

void GlRenderer::upload_face_areas(std::span<const float> face_areas)
{
    glBindBuffer(GL_TEXTURE_BUFFER, gl_->face_area);
    glBufferSubData(GL_TEXTURE_BUFFER, 0,
                    static_cast<GLsizeiptr>(face_areas.size() * sizeof(float)), face_areas.data());
    ++face_area_uploads_;
    face_areas_current_ = true;
}

void GlRenderer::set_vertex_colors(std::span<const float> rgb)
{
    ++content_version_; // the view drawn last no longer shows it
    has_colors_ = !rgb.empty();
    if (has_colors_ && rgb.size() != positions_.size())
        throw RenderError("GlRenderer::set_vertex_colors: " + std::to_string(rgb.size()) +
                          " values for " + std::to_string(positions_.size() / 3) + " vertices");
    update<float>(GL_ARRAY_BUFFER, gl_->colors, rgb, color_bytes_, buffer_allocations_);
    check("set_vertex_colors");
}

void GlRenderer::set_selection(std::span<const char> vertices, std::span<const char> faces)
{
    ++content_version_; // the view drawn last no longer shows it
    if (vertices.size() != vertex_count_ || faces.size() != face_count_)
        throw RenderError("GlRenderer::set_selection: " + std::to_string(vertices.size()) +
                          " vertex and " + std::to_string(faces.size()) +
                          " face flags for a mesh of " + std::to_string(vertex_count_) + " and " +
                          std::to_string(face_count_));
    // The face flags go into their buffer in place; the selected vertices' list is rebuilt
    // (its length changes with the selection, which changes far less often than frames).
    glBindBuffer(GL_TEXTURE_BUFFER, gl_->face_selected);
    glBufferSubData(GL_TEXTURE_BUFFER, 0, static_cast<GLsizeiptr>(faces.size()), faces.data());
    glBindBuffer(GL_ARRAY_BUFFER, gl_->vertex_selected);
    glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(vertices.size()), vertices.data());
    std::vector<std::uint32_t> selected;
    for (size_t i = 0; i < vertices.size(); ++i)
        if (vertices[i])
            selected.push_back(static_cast<std::uint32_t>(i));
    any_vertex_selected_ = !selected.empty();
    any_face_selected_ = std::any_of(faces.begin(), faces.end(), [](char c) { return c != 0; });
    glBindVertexArray(gl_->lines_vao);
    upload<std::uint32_t>(GL_ELEMENT_ARRAY_BUFFER, gl_->selected_points, selected,
                          buffer_allocations_);
    glBindVertexArray(0);
    gl_->selected_point_count = static_cast<GLsizei>(selected.size());
    check("set_selection");
}

void GlRenderer::set_glyphs(std::span<const GlyphGroup> groups)
{
    ++content_version_; // the view drawn last no longer shows it
    std::vector<float> points;
    glyphs_.clear();
    for (const GlyphGroup& g : groups)
    {
        const int first = static_cast<int>(points.size() / 3);
        const size_t per = g.shape == GlyphGroup::Shape::Segments ? 6 : 3;
        const size_t n = g.points.size() / per * per; // whole glyphs only
        points.insert(points.end(), g.points.begin(), g.points.begin() + static_cast<long>(n));
        if (n > 0)
            glyphs_.push_back({g.shape, g.color, g.size_px, first, static_cast<int>(n / 3)});
    }
    update<float>(GL_ARRAY_BUFFER, gl_->glyph_points, points, glyph_bytes_, buffer_allocations_);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    check("set_glyphs");
}

void GlRenderer::draw(const Camera& camera, const DisplayOptions& o, const ViewRect& rect)
{
    const int width = std::max(rect.width, 1), height = std::max(rect.height, 1);
    const double aspect = double(width) / height;
    const glm::dmat4 view = camera.view_matrix();
    const glm::dmat4 projection = camera.projection_matrix(aspect);
    GLint target = 0; // the window's or OSMesa's framebuffer, or whatever the caller bound
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
    // The whole target in the background colour, as before the view was kept: whatever the
    // interface draws around and over the view starts from it.
    glDisable(GL_SCISSOR_TEST);
    glClearColor(o.background[0], o.background[1], o.background[2], 1.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    // Most frames of an editor change nothing in the view (a panel hovered, a slider of
    // the interface dragged, the half-second redraw): the mesh is rasterized again only
    // when its data, the camera, the display options or the view's size changed, else the
    // view drawn last is copied. On a million-triangle mesh in software that is a frame
    // of a few milliseconds instead of a third of a second.
    const bool same = view_renders_ > 0 && drawn_.version == content_version_ &&
                      drawn_.options == o && drawn_.width == width && drawn_.height == height &&
                      drawn_.view == view && drawn_.projection == projection;
    if (!same)
    {
        gl_->view.prepare(width, height);
        render_view(glm::mat4(view), glm::mat4(projection), camera, o, width, height);
        drawn_ = {content_version_, o, width, height, view, projection};
        ++view_renders_;
    }
    // GL counts rows from the bottom.
    const int bottom = rect.framebuffer_height - rect.y - height;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, gl_->view.framebuffer);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(target));
    glBlitFramebuffer(0, 0, width, height, rect.x, bottom, rect.x + width, bottom + height,
                      GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(target));
    glViewport(rect.x, bottom, width, height);
    check("draw");
}

void GlRenderer::render_view(const glm::mat4& view, const glm::mat4& projection,
                             const Camera& camera, const DisplayOptions& o, int width, int height)
{
    glViewport(0, 0, width, height);
    glClearColor(o.background[0], o.background[1], o.background[2], 1.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);

    // The surface, pushed back a little so that edges and points drawn on it win; the
    // wireframe with it.
    const bool flat = o.shading == Shading::Flat;
    // Flat shading reads the area vectors of polygons; a triangle's plane is its own.
    flat_drawn_ = flat && !triangles_only_;
    const bool colors = o.vertex_colors && has_colors_;
    const unsigned variant = with_triangle_id(
        (flat ? kFlat : 0u) | (triangles_only_ ? kTrianglesOnly : 0u) |
        (colors ? kVertexColors : 0u) | (any_vertex_selected_ ? kVertexSelection : 0u) |
        (any_face_selected_ ? kFaceSelection : 0u) | (o.wireframe ? kWireframe : 0u));
    const bool pulled = (variant & kTriangleId) != 0;
    if (flat_drawn_ && !face_areas_current_)
    {
        // Flat shading of polygons turned on after updates that left the area vectors out:
        // from the positions the GPU has, once.
        face_area_vectors(positions_, connectivity_, face_areas_);
        upload_face_areas(face_areas_);
    }
    const gl::Program& surface = gl_->surface_variant(variant);
    surface.use();
    set_matrices(surface, view, projection);
    glUniform1i(surface["u_back_tint"], o.back_face_tint);
    // The direction to the eye at a pixel's centre, from its window coordinates: the ray
    // through it, x / -z = x_ndc / P00 (the same for y), in a perspective view.
    if (camera.projection == Projection::Perspective)
        glUniform4f(surface["u_eye_ray"], 2.0f / (float(width) * projection[0][0]),
                    2.0f / (float(height) * projection[1][1]), -1.0f / projection[0][0],
                    -1.0f / projection[1][1]);
    else
        glUniform4f(surface["u_eye_ray"], 0, 0, 0, 0);
    const palette::Rgb &sel = palette::kSelection, &back = palette::kBackFace;
    glUniform3f(surface["u_back_face_color"], back[0], back[1], back[2]);
    if (!colors)
        glUniform3f(surface["u_surface_color"], o.surface_color[0], o.surface_color[1],
                    o.surface_color[2]);
    if (variant & (kVertexSelection | kFaceSelection))
        glUniform3f(surface["u_selection_color"], sel[0], sel[1], sel[2]);
    const bool polygons = !triangles_only_;
    if (polygons && (variant & (kFlat | kFaceSelection)))
        glUniform1i(surface["u_triangle_face"], kTriangleFaceUnit);
    if (polygons && flat_drawn_)
        glUniform1i(surface["u_face_area"], kFaceAreaUnit);
    if (any_face_selected_)
        glUniform1i(surface["u_face_selected"], kFaceSelectedUnit);
    if (pulled)
    {
        glUniform1i(surface["u_triangle_corners"], kTriangleCornersUnit);
        glUniform1i(surface["u_positions"], kPositionsUnit);
        if (!flat)
            glUniform1i(surface["u_normals"], kNormalsUnit);
        if (colors)
            glUniform1i(surface["u_colors"], kColorsUnit);
        if (any_vertex_selected_)
            glUniform1i(surface["u_vertex_selected"], kVertexSelectedUnit);
    }
    if (o.wireframe)
    {
        if (polygons)
            glUniform1i(surface["u_triangle_edges"], kTriangleEdgesUnit);
        glUniform1f(surface["u_edge_width_px"], o.edge_width_px);
        glUniform3f(surface["u_edge_color"], 0.08f, 0.08f, 0.10f);
    }
    gl_->bind_face_textures();
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 1.0f);
    if (pulled)
    {
        // Three vertices a triangle, each reading its corner (mesh.vert).
        glBindVertexArray(gl_->pulled_vao);
        glDrawArrays(GL_TRIANGLES, 0, triangle_indices_);
    }
    else
    {
        glBindVertexArray(gl_->surface_vao);
        if (colors)
            glEnableVertexAttribArray(kColor);
        else
            glDisableVertexAttribArray(kColor);
        glDrawElements(GL_TRIANGLES, triangle_indices_, GL_UNSIGNED_INT, nullptr);
    }
    glDisable(GL_POLYGON_OFFSET_FILL);

    glBindVertexArray(gl_->lines_vao);
    const auto draw_edges = [&](GLuint buffer, size_t count, float width_px,
                                const glm::vec4& color) {
        if (count == 0)
            return;
        glUniform1f(gl_->lines["u_width_px"], width_px);
        glUniform4f(gl_->lines["u_color"], color.r, color.g, color.b, color.a);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffer);
        glDrawElements(GL_LINES, static_cast<GLsizei>(count), GL_UNSIGNED_INT, nullptr);
    };
    gl_->lines.use();
    set_matrices(gl_->lines, view, projection);
    glUniform2f(gl_->lines["u_viewport_px"], float(width), float(height));
    glUniform1f(gl_->lines["u_depth_bias"], 2e-5f);
    if (o.boundary_edges)
    {
        const palette::Rgb& b = palette::kBoundary;
        const palette::Rgb& s = palette::kSingular;
        draw_edges(gl_->boundary, boundary_indices_, 2.5f * o.edge_width_px, {b[0], b[1], b[2], 1});
        draw_edges(gl_->singular, singular_indices_, 2.5f * o.edge_width_px, {s[0], s[1], s[2], 1});
    }
    if (o.vertex_points)
    {
        gl_->points.use();
        set_matrices(gl_->points, view, projection);
        glUniform2f(gl_->points["u_viewport_px"], float(width), float(height));
        glUniform1f(gl_->points["u_size_px"], o.point_size_px);
        glUniform1f(gl_->points["u_depth_bias"], 4e-5f);
        glUniform4f(gl_->points["u_color"], 0.10f, 0.20f, 0.55f, 1.0f);
        glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(vertex_count_));
    }
    // Selected vertices tint the surface (mesh.frag); with the vertex points shown they are
    // also dots, darker than the tint, over the others.
    if (gl_->selected_point_count > 0 && o.vertex_points)
    {
        // Selected vertices: small dots of the selection's colour, so that the surface
        // between them stays readable on a dense mesh.
        gl_->points.use();
        set_matrices(gl_->points, view, projection);
        glUniform2f(gl_->points["u_viewport_px"], float(width), float(height));
        glUniform1f(gl_->points["u_size_px"], std::max(2.0f, o.point_size_px - 2));
        glUniform1f(gl_->points["u_depth_bias"], 6e-5f);
        // Darker than the tint they sit in, so that each stays visible.
        const palette::Rgb& c = palette::kSelection;
        glUniform4f(gl_->points["u_color"], 0.45f * c[0], 0.45f * c[1], 0.45f * c[2], 1.0f);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gl_->selected_points);
        glDrawElements(GL_POINTS, gl_->selected_point_count, GL_UNSIGNED_INT, nullptr);
    }
    if (!glyphs_.empty())
    {
        // The constraint sets' glyphs, over the selection.
        glBindVertexArray(gl_->glyph_vao);
        for (const GlyphRange& g : glyphs_)
        {
            const bool dots = g.shape == GlyphGroup::Shape::Dots;
            gl::Program& program = dots ? gl_->points : gl_->lines;
            program.use();
            set_matrices(program, view, projection);
            glUniform2f(program["u_viewport_px"], float(width), float(height));
            glUniform1f(program[dots ? "u_size_px" : "u_width_px"], g.size_px);
            glUniform1f(program["u_depth_bias"], 8e-5f);
            glUniform4f(program["u_color"], g.color[0], g.color[1], g.color[2], 1.0f);
            glDrawArrays(dots ? GL_POINTS : GL_LINES, g.first, g.count);
        }
    }
    glBindVertexArray(0);
    glUseProgram(0);
}

Image GlRenderer::read_pixels(int width, int height)
{
    Image image{width, height, std::vector<std::uint8_t>(size_t{4} * width * height)};
    std::vector<std::uint8_t> bottom_up(image.rgba.size());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bottom_up.data());
    const size_t row = size_t{4} * width;
    for (int y = 0; y < height; ++y)
        std::copy_n(&bottom_up[row * (height - 1 - y)], row, &image.rgba[row * y]);
    check("read_pixels");
    return image;
}

void GlRenderer::render_ids(const Camera& camera, int width, int height)
{
    gl_->pick.prepare(width, height);
    glViewport(0, 0, width, height);
    const GLuint background[4] = {0, 0, 0, 0};
    glClearBufferuiv(GL_COLOR, 0, background);
    const GLfloat far = 1.0f;
    glClearBufferfv(GL_DEPTH, 0, &far);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    const double aspect = double(width) / std::max(height, 1);
    gl_->ids.use();
    set_matrices(gl_->ids, glm::mat4(camera.view_matrix()),
                 glm::mat4(camera.projection_matrix(aspect)));
    glUniform1i(gl_->ids["u_triangle_face"], kTriangleFaceUnit);
    glUniform2f(gl_->ids["u_viewport_px"], float(width), float(height));
    gl_->bind_face_textures();
    glBindVertexArray(gl_->surface_vao);
    glDrawElements(GL_TRIANGLES, triangle_indices_, GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
    glUseProgram(0);
}

PickResult GlRenderer::pick(const Camera& camera, const ViewRect& rect, int x, int y)
{
    PickResult result;
    const int width = rect.width, height = rect.height;
    if (x < 0 || y < 0 || x >= width || y >= height)
        return result;
    GLint previous_framebuffer = 0;
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previous_framebuffer);
    render_ids(camera, width, height);
    GLuint ids[2] = {0, 0};
    GLfloat depth = 1.0f;
    const int row = height - 1 - y;
    glReadPixels(x, row, 1, 1, GL_RG_INTEGER, GL_UNSIGNED_INT, ids);
    glReadPixels(x, row, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
    glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previous_framebuffer));
    check("pick");
    if (ids[0] == 0)
        return result;
    result.hit = true;
    result.face = static_cast<Index>(ids[0] - 1);
    result.vertex = static_cast<Index>(ids[1] - 1);
    result.point = camera.unproject({x + 0.5, y + 0.5, depth}, width, height);
    return result;
}

Visibility GlRenderer::visibility(const Camera& camera, const ViewRect& rect)
{
    const int width = std::max(rect.width, 1), height = std::max(rect.height, 1);
    GLint previous_framebuffer = 0;
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previous_framebuffer);
    render_ids(camera, width, height);
    const size_t pixels = size_t(width) * height;
    std::vector<GLuint> ids(2 * pixels);
    std::vector<GLfloat> depth(pixels);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RG_INTEGER, GL_UNSIGNED_INT, ids.data());
    glReadPixels(0, 0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
    glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previous_framebuffer));
    check("visibility");

    Visibility v;
    v.faces.assign(face_count_, 0);
    for (size_t p = 0; p < pixels; ++p)
        if (ids[2 * p] != 0)
            v.faces[ids[2 * p] - 1] = 1;
    v.projected = project_points(camera, positions_, width, height);
    v.vertices.assign(vertex_count_, 0);
    parallel_for(static_cast<Index>(vertex_count_), [&](Index i) {
        const ScreenPoint& s = v.projected[static_cast<size_t>(i)];
        if (!(s.depth >= 0 && s.depth <= 1 && s.x >= 0 && s.y >= 0 && s.x < width && s.y < height))
            return;
        // Not behind the surface drawn around the vertex's pixel: the farthest surface depth
        // of the 3 x 3 pixels there, since a pixel's centre is up to 0.7 px from the vertex
        // and a steep (silhouette) surface changes depth fast across a pixel. Background
        // pixels do not count, or every vertex just behind a silhouette would pass; with
        // only background around, nothing hides the vertex.
        const int px = static_cast<int>(s.x), row = height - 1 - static_cast<int>(s.y);
        float farthest = -1;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
            {
                const int x = std::clamp(px + dx, 0, width - 1);
                const int y = std::clamp(row + dy, 0, height - 1);
                const float d = depth[size_t(y) * width + size_t(x)];
                if (d < 1.0f)
                    farthest = std::max(farthest, d);
            }
        v.vertices[static_cast<size_t>(i)] =
            farthest < 0 || s.depth <= farthest + kVisibilityDepthMargin;
    });
    return v;
}

} // namespace meshfair::app
