#version 330 core
// Headlight shading, lit on both sides. Flat shading takes the polygon's own normal: for a
// mesh of triangles the plane of the triangle drawn (from the derivatives of its view
// position, no memory read), for polygons their area vector, fetched through the
// triangle's face, so that a fan-triangulated quad is shaded as one polygon. Back faces
// are tinted so that holes and flipped faces show. The wireframe is drawn here rather than
// as geometry of its own: a pixel within half its width of one of its triangle's polygon
// edges (never a fan diagonal) takes the edge colour, the distances from the window
// barycentric coordinates mesh.vert gives each corner.
//
// GlRenderer compiles the variants a frame needs, each reading and interpolating only what
// it shows: FLAT, TRIANGLES (every face a triangle: the triangle drawn is its face, all its
// sides edges), VERTEX_COLORS, VERTEX_SELECTION, FACE_SELECTION, WIREFRAME, and
// TRIANGLE_ID (mesh.vert: unindexed triangles, each fragment knowing its own as
// v_triangle) for those that need it, the wireframe among them.
#ifndef FLAT
in vec3 v_normal_view;
#else
in vec3 v_position_view;
#endif
#ifdef VERTEX_COLORS
in vec3 v_color;
#else
uniform vec3 u_surface_color;
#endif
#ifdef VERTEX_SELECTION
in float v_selected;
#endif
#ifdef TRIANGLE_ID
flat in int v_triangle;
#endif

uniform mat4 u_view;
uniform bool u_back_tint;
// The direction to the eye at a pixel: normalize(-(xy * scale + offset), 1) in view space,
// u_eye_ray = (scale, offset); all 0 in an orthographic view.
uniform vec4 u_eye_ray;
uniform vec3 u_back_face_color;
#if defined(FACE_SELECTION) || defined(VERTEX_SELECTION)
uniform vec3 u_selection_color;
#endif
#if (defined(FLAT) || defined(FACE_SELECTION)) && !defined(TRIANGLES)
uniform usamplerBuffer u_triangle_face;
#define FACE_OF_TRIANGLE
#endif
#if defined(FLAT) && !defined(TRIANGLES)
uniform samplerBuffer u_face_area;
#endif
#ifdef FACE_SELECTION
uniform usamplerBuffer u_face_selected;
#endif
#ifdef WIREFRAME
noperspective in vec3 v_sides;
uniform float u_edge_width_px;
uniform vec3 u_edge_color;
#endif

out vec4 frag_color;

void main()
{
#ifdef FACE_OF_TRIANGLE
    int f = int(texelFetch(u_triangle_face, v_triangle).r);
#elif defined(FACE_SELECTION)
    int f = v_triangle;
#endif
    vec3 to_eye = normalize(vec3(-(gl_FragCoord.xy * u_eye_ray.xy + u_eye_ray.zw), 1.0));
#ifndef FLAT
    vec3 n = v_normal_view;
#elif defined(TRIANGLES)
    vec3 n = cross(dFdx(v_position_view), dFdy(v_position_view));
#else
    vec3 n = mat3(u_view) * texelFetch(u_face_area, f).xyz;
#endif
    float len = length(n);
    n = len > 0.0 ? n / len : vec3(0.0, 0.0, 1.0);
    if (dot(n, to_eye) < 0.0)
        n = -n;
#ifdef VERTEX_COLORS
    vec3 base = v_color;
#else
    vec3 base = u_surface_color;
#endif
    if (!gl_FrontFacing && u_back_tint)
        base = mix(base, u_back_face_color, 0.65);
#ifdef FACE_SELECTION
    if (texelFetch(u_face_selected, f).r != 0u)
        base = mix(base, u_selection_color, 0.55); // a selected face
#ifdef VERTEX_SELECTION
    else
        base = mix(base, u_selection_color, 0.55 * v_selected);
#endif
#elif defined(VERTEX_SELECTION)
    // Selected vertices tint the surface around them, which stays shaded and readable
    // however dense the mesh.
    base = mix(base, u_selection_color, 0.55 * v_selected);
#endif
    float diffuse = max(dot(n, to_eye), 0.0);
    float specular = pow(diffuse, 48.0);
    frag_color = vec4(base * (0.20 + 0.80 * diffuse) + vec3(0.16) * specular, 1.0);
#ifdef WIREFRAME
    // Each barycentric coordinate over its gradient in the window: the distance in pixels
    // to the side it vanishes on (exact: it is affine in the window).
    vec3 gradient = sqrt(dFdx(v_sides) * dFdx(v_sides) + dFdy(v_sides) * dFdy(v_sides));
    vec3 d = v_sides / max(gradient, vec3(1e-30));
    if (min(min(d.x, d.y), d.z) <= 0.5 * u_edge_width_px)
        frag_color = vec4(u_edge_color, 1.0);
#endif
}
