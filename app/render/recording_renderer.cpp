// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/render/recording_renderer.h"

#include <algorithm>
#include <cmath>

namespace meshfair::app {

void RecordingRenderer::set_mesh(const Mesh& mesh, const MeshDrawData&)
{
    ++calls_.set_mesh;
    face_offsets_ = mesh.face_offsets;
    face_vertices_ = mesh.face_vertices;
    positions_.assign(mesh.positions.begin(), mesh.positions.end());
    selected_vertices_.assign(static_cast<size_t>(mesh.vertex_count()), 0);
    selected_faces_.assign(static_cast<size_t>(mesh.face_count()), 0);
    glyphs_.clear();
}

void RecordingRenderer::update_positions(std::span<const Scalar> positions)
{
    ++calls_.update_positions;
    positions_.assign(positions.begin(), positions.end());
}

void RecordingRenderer::update_geometry(const DisplayGeometry& geometry)
{
    ++calls_.update_geometry;
    positions_.assign(geometry.positions.begin(), geometry.positions.end());
}

void RecordingRenderer::set_vertex_colors(std::span<const float> rgb)
{
    ++calls_.vertex_colors;
    vertex_colors_.assign(rgb.begin(), rgb.end());
}

void RecordingRenderer::set_selection(std::span<const char> vertices, std::span<const char> faces)
{
    ++calls_.selection;
    selected_vertices_.assign(vertices.begin(), vertices.end());
    selected_faces_.assign(faces.begin(), faces.end());
}

void RecordingRenderer::set_glyphs(std::span<const GlyphGroup> groups)
{
    ++calls_.glyphs;
    glyphs_.assign(groups.begin(), groups.end());
}

void RecordingRenderer::draw(const Camera&, const DisplayOptions& options, const ViewRect&)
{
    ++calls_.draw;
    options_ = options;
}

Image RecordingRenderer::read_pixels(int width, int height)
{
    Image image;
    image.width = width;
    image.height = height;
    image.rgba.assign(4 * static_cast<size_t>(width) * static_cast<size_t>(height), 0);
    return image;
}

void RecordingRenderer::rasterize(const Camera& camera, int width, int height)
{
    projected_ = project_points(camera, positions_, width, height);
    depth_.assign(static_cast<size_t>(width) * static_cast<size_t>(height), 1.0f);
    face_at_.assign(depth_.size(), -1);
    triangle_at_.assign(depth_.size(), 0);
    const Index faces = static_cast<Index>(face_offsets_.size()) - 1;
    for (Index f = 0; f < faces; ++f)
    {
        const auto begin = static_cast<size_t>(face_offsets_[static_cast<size_t>(f)]);
        const auto end = static_cast<size_t>(face_offsets_[static_cast<size_t>(f) + 1]);
        const ScreenPoint& a = projected_[static_cast<size_t>(face_vertices_[begin])];
        for (size_t k = begin + 1; k + 1 < end; ++k) // the fan the GL renderer draws
        {
            const ScreenPoint& b = projected_[static_cast<size_t>(face_vertices_[k])];
            const ScreenPoint& c = projected_[static_cast<size_t>(face_vertices_[k + 1])];
            const double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
            if (area == 0 || a.depth < 0 || b.depth < 0 || c.depth < 0 || a.depth > 1 ||
                b.depth > 1 || c.depth > 1)
                continue; // degenerate on screen, or clipped by the near or far plane
            const int x0 = std::max(0, static_cast<int>(std::floor(std::min({a.x, b.x, c.x}))));
            const int x1 =
                std::min(width - 1, static_cast<int>(std::ceil(std::max({a.x, b.x, c.x}))));
            const int y0 = std::max(0, static_cast<int>(std::floor(std::min({a.y, b.y, c.y}))));
            const int y1 =
                std::min(height - 1, static_cast<int>(std::ceil(std::max({a.y, b.y, c.y}))));
            for (int y = y0; y <= y1; ++y)
                for (int x = x0; x <= x1; ++x)
                {
                    const double px = x + 0.5, py = y + 0.5;
                    const double wa = ((b.x - px) * (c.y - py) - (b.y - py) * (c.x - px)) / area;
                    const double wb = ((c.x - px) * (a.y - py) - (c.y - py) * (a.x - px)) / area;
                    const double wc = 1 - wa - wb;
                    if (wa < 0 || wb < 0 || wc < 0)
                        continue;
                    const auto z = static_cast<float>(wa * a.depth + wb * b.depth + wc * c.depth);
                    const size_t p = static_cast<size_t>(y) * static_cast<size_t>(width) +
                                     static_cast<size_t>(x);
                    if (z < depth_[p])
                    {
                        depth_[p] = z;
                        face_at_[p] = f;
                        triangle_at_[p] = k;
                    }
                }
        }
    }
}

PickResult RecordingRenderer::pick(const Camera& camera, const ViewRect& view, int x, int y)
{
    ++calls_.pick;
    const int width = std::max(view.width, 1), height = std::max(view.height, 1);
    PickResult result;
    if (x < 0 || y < 0 || x >= width || y >= height)
        return result;
    rasterize(camera, width, height);
    const size_t p = static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x);
    if (face_at_[p] < 0)
        return result;
    result.hit = true;
    result.face = face_at_[p];
    // The corner nearest to the cursor on screen of the fan triangle drawn there (not of the
    // whole face: the ID buffer's rule, Renderer::pick), the first of equally near ones.
    double best = 1e300;
    const size_t k = triangle_at_[p];
    for (const size_t corner :
         {static_cast<size_t>(face_offsets_[static_cast<size_t>(result.face)]), k, k + 1})
    {
        const ScreenPoint& s = projected_[static_cast<size_t>(face_vertices_[corner])];
        const double d = (s.x - x - 0.5) * (s.x - x - 0.5) + (s.y - y - 0.5) * (s.y - y - 0.5);
        if (d < best)
        {
            best = d;
            result.vertex = face_vertices_[corner];
        }
    }
    result.point = camera.unproject({x + 0.5, y + 0.5, depth_[p]}, width, height);
    return result;
}

Visibility RecordingRenderer::visibility(const Camera& camera, const ViewRect& view)
{
    ++calls_.visibility;
    const int width = std::max(view.width, 1), height = std::max(view.height, 1);
    rasterize(camera, width, height);
    Visibility v;
    v.faces.assign(face_offsets_.empty() ? 0 : face_offsets_.size() - 1, 0);
    for (const Index f : face_at_)
        if (f >= 0)
            v.faces[static_cast<size_t>(f)] = 1;
    v.projected = projected_;
    v.vertices.assign(projected_.size(), 0);
    for (size_t i = 0; i < projected_.size(); ++i)
    {
        const ScreenPoint& s = projected_[i];
        if (!(s.depth >= 0 && s.depth <= 1 && s.x >= 0 && s.y >= 0 && s.x < width && s.y < height))
            continue;
        // The GL renderer's rule: not behind the farthest surface of the 3 x 3 pixels around.
        float farthest = -1;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
            {
                const int x = std::clamp(static_cast<int>(s.x) + dx, 0, width - 1);
                const int y = std::clamp(static_cast<int>(s.y) + dy, 0, height - 1);
                const float d = depth_[static_cast<size_t>(y) * static_cast<size_t>(width) +
                                       static_cast<size_t>(x)];
                if (d < 1.0f)
                    farthest = std::max(farthest, d);
            }
        v.vertices[i] = farthest < 0 || s.depth <= farthest + kVisibilityDepthMargin;
    }
    return v;
}

} // namespace meshfair::app
