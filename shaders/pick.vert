#version 330 core
// The ID buffer: each pixel gets its face and the nearest of its triangle's corners.
layout(location = 0) in vec3 a_position;

uniform mat4 u_view;
uniform mat4 u_projection;

flat out int v_vertex;

void main()
{
    v_vertex = gl_VertexID; // in an indexed draw, the vertex's index
    gl_Position = u_projection * u_view * vec4(a_position, 1.0);
}
