#version 330 core
// Edges (boundary, singular, glyph segments): expanded to screen-space quads by lines.geom,
// since core profiles draw no lines wider than one pixel.
layout(location = 0) in vec3 a_position;

uniform mat4 u_view;
uniform mat4 u_projection;

void main()
{
    gl_Position = u_projection * u_view * vec4(a_position, 1.0);
}
