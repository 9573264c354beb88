#version 330 core
// One line segment in, a quad of u_width_px pixels out, pulled slightly towards the
// eye (u_depth_bias, in normalized depth) so that edges stay on top of their faces.
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;

uniform vec2 u_viewport_px;
uniform float u_width_px;
uniform float u_depth_bias;

void main()
{
    vec4 a = gl_in[0].gl_Position;
    vec4 b = gl_in[1].gl_Position;
    if (a.w <= 0.0 || b.w <= 0.0)
        return; // crosses the eye plane: the near plane would clip it anyway
    vec2 sa = a.xy / a.w * u_viewport_px;
    vec2 sb = b.xy / b.w * u_viewport_px;
    vec2 d = sb - sa;
    float len = length(d);
    vec2 normal = len > 0.0 ? vec2(-d.y, d.x) / len : vec2(0.0, 1.0);
    vec2 offset = normal * u_width_px / u_viewport_px;
    a.z -= u_depth_bias * a.w;
    b.z -= u_depth_bias * b.w;
    gl_Position = a + vec4(offset * a.w, 0.0, 0.0);
    EmitVertex();
    gl_Position = a - vec4(offset * a.w, 0.0, 0.0);
    EmitVertex();
    gl_Position = b + vec4(offset * b.w, 0.0, 0.0);
    EmitVertex();
    gl_Position = b - vec4(offset * b.w, 0.0, 0.0);
    EmitVertex();
    EndPrimitive();
}
