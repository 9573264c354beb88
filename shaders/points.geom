#version 330 core
layout(points) in;
layout(triangle_strip, max_vertices = 4) out;

uniform vec2 u_viewport_px;
uniform float u_size_px;
uniform float u_depth_bias;

out vec2 g_offset_px; // from the dot's centre

void main()
{
    vec4 p = gl_in[0].gl_Position;
    if (p.w <= 0.0)
        return;
    p.z -= u_depth_bias * p.w;
    float h = 0.5 * u_size_px + 0.5;
    for (int k = 0; k < 4; ++k)
    {
        vec2 corner = vec2(k % 2 == 0 ? -h : h, k < 2 ? -h : h);
        g_offset_px = corner;
        gl_Position = p + vec4(2.0 * corner / u_viewport_px * p.w, 0.0, 0.0);
        EmitVertex();
    }
    EndPrimitive();
}
