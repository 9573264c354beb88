#version 330 core
// Vertex dots: a screen-space square per vertex (points.geom), pulled towards the eye
// like the edges. Drawn as quads rather than GL points, whose rasterization is placed
// differently by different drivers.
layout(location = 0) in vec3 a_position;

uniform mat4 u_view;
uniform mat4 u_projection;

void main()
{
    gl_Position = u_projection * u_view * vec4(a_position, 1.0);
}
