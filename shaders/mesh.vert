#version 330 core
// The surface: positions and normals in view space for the headlight, and the colour
// (the overlay's per-vertex colour, or a constant when the overlay is off).
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_color;
layout(location = 3) in float a_selected; // 1 for a selected vertex

uniform mat4 u_view;
uniform mat4 u_projection;

out vec3 v_position_view;
out vec3 v_normal_view;
out vec3 v_color;
out float v_selected;

void main()
{
    vec4 p = u_view * vec4(a_position, 1.0);
    v_position_view = p.xyz;
    v_normal_view = mat3(u_view) * a_normal; // the view matrix is a rigid motion
    v_color = a_color;
    v_selected = a_selected;
    gl_Position = u_projection * p;
}
