// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/energies/volume_constraint.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/errors.h"
#include "core/parallel/parallel.h"

namespace meshfair {

namespace {

const Scalar* at(std::span<const Scalar> x, Index v)
{
    return x.data() + 3 * static_cast<std::ptrdiff_t>(v);
}

Scalar det3(const Scalar* a, const Scalar* b, const Scalar* c)
{
    return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
           a[2] * (b[0] * c[1] - b[1] * c[0]);
}

//! out += a x b
void add_cross(const Scalar* a, const Scalar* b, Scalar* out)
{
    out[0] += a[1] * b[2] - a[2] * b[1];
    out[1] += a[2] * b[0] - a[0] * b[2];
    out[2] += a[0] * b[1] - a[1] * b[0];
}

Index find_root(std::vector<Index>& parent, Index v)
{
    while (parent[v] != v)
    {
        parent[v] = parent[parent[v]];
        v = parent[v];
    }
    return v;
}

//! The coefficients of 6 V(x + t g) in t, as sums over faces.
struct Cubic
{
    Scalar c[4] = {0, 0, 0, 0};
    Cubic& operator+=(const Cubic& o)
    {
        for (int d = 0; d < 4; ++d)
            c[d] += o.c[d];
        return *this;
    }
};

//! Triangles taken kLanes at a time, their corners gathered lane by lane so that the
//! determinants run on whole vectors; each lane computes what the face-by-face loop of
//! VolumeConstraint::project computes, in the same order, and the lanes are summed in
//! face order: the same bits.
constexpr Index kLanes = 4;

//! det3 of lane l of three gathered points (the same products in the same order).
Scalar lane_det3(const Scalar (&a)[3][kLanes], const Scalar (&b)[3][kLanes],
                 const Scalar (&c)[3][kLanes], int l)
{
    return a[0][l] * (b[1][l] * c[2][l] - b[2][l] * c[1][l]) -
           a[1][l] * (b[0][l] * c[2][l] - b[2][l] * c[0][l]) +
           a[2][l] * (b[0][l] * c[1][l] - b[1][l] * c[0][l]);
}

//! Adds the cubic's four coefficients of the kLanes triangles listed at `faces`.
void add_triangle_cubics(const Mesh& mesh, std::span<const Scalar> x, std::span<const Scalar> g,
                         const Index* faces, Cubic& sum)
{
    // p[0..2]: the corners' positions, p[3..5]: their directions; [axis][lane].
    Scalar p[6][3][kLanes];
    const Index* corners = mesh.face_vertices.data();
    for (int l = 0; l < kLanes; ++l)
        for (int c = 0; c < 3; ++c)
        {
            const Scalar* xc = at(x, corners[3 * static_cast<std::ptrdiff_t>(faces[l]) + c]);
            const Scalar* gc = at(g, corners[3 * static_cast<std::ptrdiff_t>(faces[l]) + c]);
            for (int axis = 0; axis < 3; ++axis)
            {
                p[c][axis][l] = xc[axis];
                p[3 + c][axis][l] = gc[axis];
            }
        }
    Scalar out[4][kLanes];
    for (int l = 0; l < kLanes; ++l)
    {
        // 0 + the value, as the face loop's sums start at 0.
        out[0][l] = Scalar(0) + lane_det3(p[0], p[1], p[2], l);
        out[1][l] = Scalar(0) + (lane_det3(p[3], p[1], p[2], l) + lane_det3(p[0], p[4], p[2], l) +
                                 lane_det3(p[0], p[1], p[5], l));
        out[2][l] = Scalar(0) + (lane_det3(p[0], p[4], p[5], l) + lane_det3(p[3], p[1], p[5], l) +
                                 lane_det3(p[3], p[4], p[2], l));
        out[3][l] = Scalar(0) + lane_det3(p[3], p[4], p[5], l);
    }
    for (int l = 0; l < kLanes; ++l)
        for (int d = 0; d < 4; ++d)
            sum.c[d] += out[d][l];
}

//! 6 V_f: the fan of face f from its first corner.
Scalar face_volume6(const Mesh& mesh, std::span<const Scalar> x, Index f)
{
    const std::span<const Index> face = mesh.face(f);
    Scalar sum = 0;
    for (size_t m = 1; m + 1 < face.size(); ++m)
        sum += det3(at(x, face[0]), at(x, face[m]), at(x, face[m + 1]));
    return sum;
}

} // namespace

namespace {

//! volume_gradient6 with the mesh's corner walk made once by the caller (project() calls it
//! for every free vertex of every step).
void gradient6(const Mesh& mesh, const Topology& topology, const CornerWalk& walk,
               std::span<const Scalar> x, Index i, Scalar* out)
{
    // For the fan from corner 0 of a face, d det(a, b, c) = (b x c) da + (c x a) db + (a x b) dc.
    // Summed in a local array and stored once: out may alias x for the compiler, which
    // would otherwise store and reload it at every product.
    Scalar sum[3] = {0, 0, 0};
    if (walk.triangles())
    {
        // A triangle's one fan triangle: the corner's next vertex crossed with its previous
        // one, the same products in the same order as the general case below gives.
        for (const Index corner : topology.corners_of_vertex(i))
        {
            const CornerNeighbors n = walk.neighbors(corner, walk.face(corner));
            add_cross(at(x, n.next), at(x, n.previous), sum);
        }
    }
    else
        for (const Index corner : topology.corners_of_vertex(i))
        {
            const Index f = topology.face_of_corner(corner);
            const std::span<const Index> face = mesh.face(f);
            const size_t n = face.size(), p = static_cast<size_t>(corner - mesh.face_offsets[f]);
            const Scalar* a = at(x, face[0]);
            if (p == 0)
                for (size_t m = 1; m + 1 < n; ++m)
                    add_cross(at(x, face[m]), at(x, face[m + 1]), sum);
            else
            {
                if (p + 1 < n) // x_p is the middle corner of triangle (0, p, p+1)
                    add_cross(at(x, face[p + 1]), a, sum);
                if (p >= 2) // x_p is the last corner of triangle (0, p-1, p)
                    add_cross(a, at(x, face[p - 1]), sum);
            }
        }
    for (int a = 0; a < 3; ++a)
        out[a] = sum[a];
}

} // namespace

void volume_gradient6(const Mesh& mesh, const Topology& topology, std::span<const Scalar> x,
                      Index i, Scalar* out)
{
    gradient6(mesh, topology, CornerWalk(mesh, topology), x, i, out);
}

namespace {

//! The cubic's coefficients of one triangle (a, b, c) moving along (ga, gb, gc).
void add_triangle_cubic(const Scalar* a, const Scalar* b, const Scalar* c, const Scalar* ga,
                        const Scalar* gb, const Scalar* gc, Scalar* out)
{
    out[0] += det3(a, b, c);
    out[1] += det3(ga, b, c) + det3(a, gb, c) + det3(a, b, gc);
    out[2] += det3(a, gb, gc) + det3(ga, b, gc) + det3(ga, gb, c);
    out[3] += det3(ga, gb, gc);
}

//! The centroid of the loop's vertices at x.
void loop_centroid(std::span<const Scalar> x, std::span<const Index> loop, Scalar* p)
{
    p[0] = p[1] = p[2] = 0;
    for (const Index v : loop)
        for (int a = 0; a < 3; ++a)
            p[a] += x[3 * static_cast<std::ptrdiff_t>(v) + a];
    const Scalar inv = Scalar(1) / static_cast<Scalar>(loop.size());
    for (int a = 0; a < 3; ++a)
        p[a] *= inv;
}

} // namespace

VolumeConstraint::VolumeConstraint(const Mesh& mesh, const Topology& topology,
                                   std::span<const Scalar> x, std::span<const char> fixed,
                                   OpenVolume open, bool free_components_only)
    : mesh_(&mesh), topology_(&topology), fixed_(fixed.begin(), fixed.end())
{
    const Index nv = mesh.vertex_count(), nf = mesh.face_count();
    if (nf == 0)
        throw RecipeError("volume", "the mesh has no face: it encloses no volume to keep");
    // Components: the vertices joined by faces, numbered in order of their first face.
    std::vector<Index> parent(nv);
    std::iota(parent.begin(), parent.end(), Index(0));
    for (Index f = 0; f < nf; ++f)
    {
        const std::span<const Index> face = mesh.face(f);
        const Index a = find_root(parent, face[0]);
        for (const Index v : face.subspan(1))
        {
            const Index b = find_root(parent, v);
            if (b != a)
                parent[b] = a;
        }
    }
    std::vector<Index> label(nv, kInvalidIndex), face_component(nf);
    Index count = 0;
    for (Index f = 0; f < nf; ++f)
    {
        const Index root = find_root(parent, mesh.face(f)[0]);
        if (label[root] == kInvalidIndex)
            label[root] = count++;
        face_component[f] = label[root];
    }
    // The boundary chain: how many more times the faces traverse each edge from its first
    // vertex to its second than back. A component is closed when it is 0 on every edge.
    const Index ne = topology.edge_count();
    std::vector<Index> net(ne, 0);
    for (Index f = 0; f < nf; ++f)
        for (Index k = mesh.face_offsets[f]; k < mesh.face_offsets[f + 1]; ++k)
        {
            const Index e = topology.corner_edge[k];
            net[e] += mesh.face_vertices[k] == topology.edge_vertices[2 * e] ? 1 : -1;
        }
    closed_.assign(count, 1);
    // The chain's directed edges (|net| copies each) leaving each vertex, in edge order.
    std::vector<Index> out_offsets(static_cast<size_t>(nv) + 1, 0);
    for (Index e = 0; e < ne; ++e)
        if (net[e] != 0)
        {
            const Index from = topology.edge_vertices[2 * e + (net[e] > 0 ? 0 : 1)];
            out_offsets[from + 1] += std::abs(net[e]);
            closed_[label[find_root(parent, from)]] = 0;
        }
    std::partial_sum(out_offsets.begin(), out_offsets.end(), out_offsets.begin());
    const Index chain_edges = out_offsets.back();
    std::vector<Index> out_to(chain_edges), out_next(out_offsets.begin(), out_offsets.end() - 1);
    for (Index e = 0; e < ne; ++e)
        for (Index copy = 0; copy < std::abs(net[e]); ++copy)
        {
            const Index from = topology.edge_vertices[2 * e + (net[e] > 0 ? 0 : 1)],
                        to = topology.edge_vertices[2 * e + (net[e] > 0 ? 1 : 0)];
            out_to[out_next[from]++] = to;
        }
    // Loops: in-degree equals out-degree at every vertex (the boundary of a boundary is
    // 0), so a walk along unused chain edges from a vertex comes back to it. Walks start
    // at the first unused edge in vertex order; each loop joins its component's list.
    std::vector<Index> loop_component;
    if (open == OpenVolume::Capped && chain_edges > 0)
    {
        std::copy(out_offsets.begin(), out_offsets.end() - 1, out_next.begin()); // next unused
        for (Index start = 0; start < nv; ++start)
            while (out_next[start] < out_offsets[start + 1])
            {
                Index v = start;
                do
                {
                    loop_vertices_.push_back(v);
                    v = out_to[out_next[v]++];
                } while (v != start);
                loop_offsets_.push_back(static_cast<Index>(loop_vertices_.size()));
                loop_component.push_back(label[find_root(parent, start)]);
            }
    }
    // The loops of each component (CSR over the loops, renumbered component by component).
    {
        // A counting sort by component, each component's loops in the order they were found.
        component_loops_.assign(static_cast<size_t>(count) + 1, 0);
        for (const Index c : loop_component)
            ++component_loops_[c + 1];
        std::partial_sum(component_loops_.begin(), component_loops_.end(),
                         component_loops_.begin());
        std::vector<Index> order(loop_component.size());
        std::vector<Index> next(component_loops_.begin(), component_loops_.end() - 1);
        for (Index l = 0; l < static_cast<Index>(loop_component.size()); ++l)
            order[next[loop_component[l]]++] = l;
        std::vector<Index> offsets{0}, vertices;
        vertices.reserve(loop_vertices_.size());
        for (const Index l : order)
        {
            vertices.insert(vertices.end(), loop_vertices_.begin() + loop_offsets_[l],
                            loop_vertices_.begin() + loop_offsets_[l + 1]);
            offsets.push_back(static_cast<Index>(vertices.size()));
        }
        loop_offsets_ = std::move(offsets);
        loop_vertices_ = std::move(vertices);
    }
    // The kept components; their faces and free vertices, in CSR form.
    kept_.assign(count, 0);
    for (Index c = 0; c < count; ++c)
        kept_[c] = static_cast<char>(closed_[c] || open == OpenVolume::Capped);
    Index held = 0;
    if (free_components_only)
    {
        std::vector<char> holds(count, 0);
        for (Index v = 0; v < nv; ++v)
            if (fixed[v] && label[find_root(parent, v)] != kInvalidIndex &&
                topology.corners_of_vertex(v).size() > 0)
                holds[label[find_root(parent, v)]] = 1;
        for (Index c = 0; c < count; ++c)
            if (holds[c] && kept_[c])
            {
                kept_[c] = 0;
                ++held;
            }
    }
    const auto kept = [&](Index c) { return kept_[c] != 0; };
    face_offsets_.assign(static_cast<size_t>(count) + 1, 0);
    vertex_offsets_.assign(static_cast<size_t>(count) + 1, 0);
    for (Index f = 0; f < nf; ++f)
        if (kept(face_component[f]))
            ++face_offsets_[face_component[f] + 1];
    std::vector<Index> vertex_component(nv, kInvalidIndex);
    for (Index v = 0; v < nv; ++v)
        if (label[find_root(parent, v)] != kInvalidIndex &&
            topology.corners_of_vertex(v).size() > 0)
        {
            vertex_component[v] = label[find_root(parent, v)];
            if (kept(vertex_component[v]) && !fixed[v])
                ++vertex_offsets_[vertex_component[v] + 1];
        }
    std::partial_sum(face_offsets_.begin(), face_offsets_.end(), face_offsets_.begin());
    std::partial_sum(vertex_offsets_.begin(), vertex_offsets_.end(), vertex_offsets_.begin());
    faces_.resize(face_offsets_.back());
    vertices_.resize(vertex_offsets_.back());
    std::vector<Index> fill_faces(face_offsets_.begin(), face_offsets_.end() - 1);
    std::vector<Index> fill_vertices(vertex_offsets_.begin(), vertex_offsets_.end() - 1);
    for (Index f = 0; f < nf; ++f)
        if (kept(face_component[f]))
            faces_[fill_faces[face_component[f]]++] = f;
    for (Index v = 0; v < nv; ++v)
        if (vertex_component[v] != kInvalidIndex && kept(vertex_component[v]) && !fixed[v])
            vertices_[fill_vertices[vertex_component[v]]++] = v;

    if (held > 0)
        notes_.push_back("volume: " + std::to_string(held) + " of " + std::to_string(count) +
                         " components hold fixed vertices (pins, or the rest around a region): "
                         "their volumes are left to the fairing (\"components\": \"free\")");
    const Index closed = closed_component_count();
    if (closed == 0 && open == OpenVolume::None)
        throw RecipeError("volume",
                          "the mesh has no closed component (each has a boundary, an edge of "
                          "three or more faces, or faces of opposite orientations): it "
                          "encloses no volume to keep (\"open\": \"capped\" keeps the volume "
                          "enclosed with the boundary loops capped)");
    target_.assign(count, 0);
    for (Index c = 0; c < count; ++c)
        if (kept(c))
            target_[c] = volume(c, x);
    if (closed < count)
    {
        // The first face of the first few open components, in face order.
        std::string first;
        Index listed = 0;
        std::vector<char> named(count, 0);
        for (Index f = 0; f < nf && listed < 5; ++f)
            if (!closed_[face_component[f]] && !named[face_component[f]])
            {
                named[face_component[f]] = 1;
                first += (listed++ ? ", " : "") + std::to_string(f);
            }
        const std::string which =
            "volume: " + std::to_string(count - closed) + " of " + std::to_string(count) +
            " components are open (a boundary, an edge of three or more faces, or faces of "
            "opposite orientations; first faces " +
            first + (count - closed > listed ? ", ..." : "") + "): ";
        notes_.push_back(which + (open == OpenVolume::Capped
                                      ? "the volume kept there is the one enclosed with their " +
                                            std::to_string(loop_count()) +
                                            " boundary loops capped by fans from the loops' "
                                            "centroids"
                                      : std::string("their volumes are not kept")));
    }
    gradient_.assign(3 * static_cast<size_t>(nv), 0);
}

Index VolumeConstraint::closed_component_count() const
{
    return static_cast<Index>(std::count(closed_.begin(), closed_.end(), 1));
}

Scalar VolumeConstraint::caps_volume6(Index component, std::span<const Scalar> x) const
{
    Scalar sum = 0;
    for (Index l = component_loops_[component]; l < component_loops_[component + 1]; ++l)
    {
        const std::span<const Index> loop(loop_vertices_.data() + loop_offsets_[l],
                                          loop_vertices_.data() + loop_offsets_[l + 1]);
        Scalar p[3];
        loop_centroid(x, loop, p);
        for (size_t k = 0; k < loop.size(); ++k)
        {
            const Index a = loop[k], b = loop[(k + 1) % loop.size()];
            sum += det3(p, at(x, b), at(x, a)); // the cap traverses a -> b backwards
        }
    }
    return sum;
}

void VolumeConstraint::add_caps_gradient(Index component, std::span<const Scalar> x,
                                         Scalar* g) const
{
    // Triangle (p, b, a) of the cap: d det = (b x a) dp + (a x p) db + (p x b) da, and
    // dp = 1/n sum_k da_k: each vertex of the loop takes 1/n of sum (b x a), u x p for the
    // edge u -> v that ends at it and p x w for the edge v -> w that starts at it.
    for (Index l = component_loops_[component]; l < component_loops_[component + 1]; ++l)
    {
        const std::span<const Index> loop(loop_vertices_.data() + loop_offsets_[l],
                                          loop_vertices_.data() + loop_offsets_[l + 1]);
        const size_t n = loop.size();
        Scalar p[3], s[3] = {0, 0, 0};
        loop_centroid(x, loop, p);
        for (size_t k = 0; k < n; ++k)
            add_cross(at(x, loop[(k + 1) % n]), at(x, loop[k]), s);
        const Scalar inv = Scalar(1) / static_cast<Scalar>(n);
        for (size_t k = 0; k < n; ++k)
        {
            const Index v = loop[k];
            if (fixed_[v])
                continue;
            Scalar sum[3] = {s[0] * inv, s[1] * inv, s[2] * inv};
            add_cross(at(x, loop[(k + n - 1) % n]), p, sum);
            add_cross(p, at(x, loop[(k + 1) % n]), sum);
            for (int a = 0; a < 3; ++a)
                g[3 * static_cast<std::ptrdiff_t>(v) + a] += sum[a];
        }
    }
}

Scalar VolumeConstraint::volume(Index component, std::span<const Scalar> x) const
{
    if (!is_kept(component))
        return 0; // its faces are not listed
    const Index begin = face_offsets_[component];
    const Index n = face_offsets_[component + 1] - begin;
    return (deterministic_sum(n,
                              [&](Index k) { return face_volume6(*mesh_, x, faces_[begin + k]); }) +
            caps_volume6(component, x)) /
           6;
}

void VolumeConstraint::project(std::span<Scalar> x, std::span<const Index> hold)
{
    gather_gradient(x);
    for (const Index v : hold)
        std::fill_n(&gradient_[3 * static_cast<size_t>(v)], 3, Scalar(0));
    move_to_targets(x);
}

void VolumeConstraint::project_along(std::span<Scalar> x, std::span<const Scalar> at,
                                     const std::function<void(std::span<Scalar>)>& direction)
{
    gather_gradient(at);
    direction(gradient_);
    move_to_targets(x);
}

void VolumeConstraint::gather_gradient(std::span<const Scalar> x)
{
    const Mesh& mesh = *mesh_;
    const Topology& topology = *topology_;
    const CornerWalk walk(mesh, topology);
    Scalar* g = gradient_.data();
    for_each_kept([&](Index component, Index vbegin, Index vcount) {
        // g_i = dV/dx_i (times 6), gathered over the corners of i: for the fan from corner
        // 0 of a face, d det(a, b, c) = (b x c) da + (c x a) db + (a x b) dc.
        parallel_for(vcount, [&](Index k) {
            const Index i = vertices_[vbegin + k];
            gradient6(mesh, topology, walk, x, i, &g[3 * static_cast<std::ptrdiff_t>(i)]);
        });
        add_caps_gradient(component, x, g);
    });
}

void VolumeConstraint::move_to_targets(std::span<Scalar> x)
{
    const Mesh& mesh = *mesh_;
    const Topology& topology = *topology_;
    const CornerWalk walk(mesh, topology);
    const Scalar* g = gradient_.data();
    for_each_kept([&](Index component, Index vbegin, Index vcount) {
        // V(x + t g) = (c0 + c1 t + c2 t^2 + c3 t^3) / 6: each fan triangle's determinant
        // expanded in t, summed in one pass over the faces (each face's four terms, then
        // the block's sums; no per-face array: four sums over one would read it four
        // times). g stays 0 at fixed vertices: only free ones are ever written.
        const Index fbegin = face_offsets_[component],
                    fcount = face_offsets_[component + 1] - fbegin;
        const std::span<const Scalar> direction = gradient_;
        Cubic cubic = deterministic_block_sums<Cubic>(fcount, [&](Index begin, Index end) {
            Cubic sum;
            Index k = begin;
            if (walk.triangles())
                for (; k + kLanes <= end; k += kLanes)
                    add_triangle_cubics(mesh, x, direction, &faces_[fbegin + k], sum);
            for (; k < end; ++k)
            {
                const std::span<const Index> face = mesh.face(faces_[fbegin + k]);
                Scalar out[4] = {0, 0, 0, 0};
                const Scalar *a = at(x, face[0]), *ga = at(direction, face[0]);
                for (size_t m = 1; m + 1 < face.size(); ++m)
                    add_triangle_cubic(a, at(x, face[m]), at(x, face[m + 1]), ga,
                                       at(direction, face[m]), at(direction, face[m + 1]), out);
                for (int d = 0; d < 4; ++d)
                    sum.c[d] += out[d];
            }
            return sum;
        });
        // The caps' triangles (p, b, a), their centroid moving with the loop's mean of g.
        Cubic caps;
        for (Index l = component_loops_[component]; l < component_loops_[component + 1]; ++l)
        {
            const std::span<const Index> loop(loop_vertices_.data() + loop_offsets_[l],
                                              loop_vertices_.data() + loop_offsets_[l + 1]);
            Scalar p[3], gp[3];
            loop_centroid(x, loop, p);
            loop_centroid(direction, loop, gp);
            for (size_t k = 0; k < loop.size(); ++k)
            {
                const Index a = loop[k], b = loop[(k + 1) % loop.size()];
                add_triangle_cubic(p, at(x, b), at(x, a), gp, at(direction, b), at(direction, a),
                                   caps.c);
            }
        }
        cubic += caps;
        const Scalar* coefficient = cubic.c;
        // Newton from t = 0 on 6 (V(t) - V_0). Along g, the gradient of 6 V, the slope at 0
        // is c1 = |g|^2: positive unless no free vertex moves the volume (along A^-1 g, A
        // positive definite, it is g^T A^-1 g > 0 too).
        const Scalar goal = 6 * target_[component];
        const auto residual = [&](Scalar t) {
            return coefficient[0] - goal +
                   t * (coefficient[1] + t * (coefficient[2] + t * coefficient[3]));
        };
        if (!(coefficient[1] > 0))
            return; // no free vertex moves the volume
        Scalar t = 0;
        for (int iteration = 0; iteration < 50; ++iteration)
        {
            const Scalar slope = coefficient[1] + t * (2 * coefficient[2] + 3 * t * coefficient[3]);
            if (!(slope > 0))
                break;
            const Scalar next = t - residual(t) / slope;
            if (next == t)
                break;
            t = next;
            if (std::abs(residual(t)) <= 1e-15 * std::abs(goal))
                break;
        }
        if (!std::isfinite(t))
            return;
        parallel_for(vcount, [&](Index k) {
            const std::ptrdiff_t i = 3 * static_cast<std::ptrdiff_t>(vertices_[vbegin + k]);
            for (int a = 0; a < 3; ++a)
                x[i + a] += t * g[i + a];
        });
    });
}

void VolumeConstraint::remove_normal_part(std::span<const Scalar> x, std::span<Scalar> r)
{
    gather_gradient(x);
    const Scalar* g = gradient_.data();
    for_each_kept([&](Index, Index vbegin, Index vcount) {
        const auto dot = [&](const Scalar* a, const Scalar* b) {
            return deterministic_sum(vcount, [&](Index k) {
                const std::ptrdiff_t i = 3 * static_cast<std::ptrdiff_t>(vertices_[vbegin + k]);
                return a[i] * b[i] + a[i + 1] * b[i + 1] + a[i + 2] * b[i + 2];
            });
        };
        const Scalar gg = dot(g, g);
        if (!(gg > 0))
            return;
        const Scalar f = dot(r.data(), g) / gg;
        parallel_for(vcount, [&](Index k) {
            const std::ptrdiff_t i = 3 * static_cast<std::ptrdiff_t>(vertices_[vbegin + k]);
            for (int a = 0; a < 3; ++a)
                r[i + a] -= f * g[i + a];
        });
    });
}

} // namespace meshfair
