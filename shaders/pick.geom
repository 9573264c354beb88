#version 330 core
// Passes each triangle on with its face and its corners' ids and window positions, from
// which the fragment shader picks the nearest corner.
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

uniform usamplerBuffer u_triangle_face;
uniform vec2 u_viewport_px;

flat in int v_vertex[];
flat out uint g_face;
flat out ivec3 g_vertices;
flat out vec2 g_window[3];

void main()
{
    uint face = texelFetch(u_triangle_face, gl_PrimitiveIDIn).r;
    ivec3 ids = ivec3(v_vertex[0], v_vertex[1], v_vertex[2]);
    vec2 window[3];
    for (int k = 0; k < 3; ++k)
    {
        vec4 p = gl_in[k].gl_Position;
        window[k] = (p.xy / max(p.w, 1e-30) * 0.5 + 0.5) * u_viewport_px;
    }
    for (int k = 0; k < 3; ++k)
    {
        g_face = face;
        g_vertices = ids;
        g_window = window;
        gl_Position = gl_in[k].gl_Position;
        EmitVertex();
    }
    EndPrimitive();
}
