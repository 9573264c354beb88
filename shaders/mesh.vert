#version 330 core
// The surface: the vertex normal in view space for the headlight, and the overlay's
// per-vertex colour and the vertex selection only in the programs that show them (the
// defines GlRenderer compiles this file with: see mesh.frag). Each output costs every
// vertex and every triangle of a software rasterizer, whatever the pixels show.
//
// With TRIANGLE_ID the triangles come unindexed, three vertices each (glDrawArrays), and
// each vertex reads its own corner from the triangles' index buffer and its attributes
// from their buffers: the fragments then know their triangle (v_triangle) without
// gl_PrimitiveID, for which a software rasterizer copies every triangle's vertices apart
// after shading them, one reallocation per triangle.
#ifdef TRIANGLE_ID
uniform usamplerBuffer u_triangle_corners; // the index buffer, one corner a texel
#if defined(WIREFRAME) && !defined(TRIANGLES)
uniform usamplerBuffer u_triangle_edges; // bit k: corner k to k + 1 is a polygon edge
#endif
uniform samplerBuffer u_positions;
#ifndef FLAT
uniform samplerBuffer u_normals;
#endif
#ifdef VERTEX_COLORS
uniform samplerBuffer u_colors;
#endif
#ifdef VERTEX_SELECTION
uniform usamplerBuffer u_vertex_selected;
#endif
flat out int v_triangle;
#ifdef WIREFRAME
// The pixel's barycentric coordinates in the window (0 on the side opposite each corner),
// 1e4 more on a fan diagonal: the wireframe's distances (mesh.frag).
noperspective out vec3 v_sides;
#endif
#else
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_color;
layout(location = 3) in float a_selected; // 1 for a selected vertex
#endif

uniform mat4 u_view;
uniform mat4 u_projection;

#ifndef FLAT
out vec3 v_normal_view;
#else
out vec3 v_position_view; // its derivatives give the triangle's plane
#endif
#ifdef VERTEX_COLORS
out vec3 v_color;
#endif
#ifdef VERTEX_SELECTION
out float v_selected;
#endif

void main()
{
#ifdef TRIANGLE_ID
    int vertex = int(texelFetch(u_triangle_corners, gl_VertexID).r);
    v_triangle = gl_VertexID / 3;
#ifdef WIREFRAME
    int corner = gl_VertexID % 3;
    v_sides = vec3(corner == 0, corner == 1, corner == 2);
#ifndef TRIANGLES
    // The side opposite corner k runs from corner k + 1 to k + 2: bit (k + 1) % 3.
    uint sides = texelFetch(u_triangle_edges, v_triangle).r;
    v_sides += 1e4 * vec3((sides & 2u) == 0u, (sides & 4u) == 0u, (sides & 1u) == 0u);
#endif
#endif
    vec3 position = texelFetch(u_positions, vertex).xyz;
#ifndef FLAT
    vec3 normal = texelFetch(u_normals, vertex).xyz;
#endif
#ifdef VERTEX_COLORS
    v_color = texelFetch(u_colors, vertex).rgb;
#endif
#ifdef VERTEX_SELECTION
    v_selected = float(texelFetch(u_vertex_selected, vertex).r);
#endif
#else
    vec3 position = a_position;
#ifndef FLAT
    vec3 normal = a_normal;
#endif
#ifdef VERTEX_COLORS
    v_color = a_color;
#endif
#ifdef VERTEX_SELECTION
    v_selected = a_selected;
#endif
#endif
    vec4 p = u_view * vec4(position, 1.0);
#ifndef FLAT
    v_normal_view = mat3(u_view) * normal; // the view matrix is a rigid motion
#else
    v_position_view = p.xyz;
#endif
    gl_Position = u_projection * p;
}
