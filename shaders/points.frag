#version 330 core
in vec2 g_offset_px;

uniform vec4 u_color;
uniform float u_size_px;

out vec4 frag_color;

void main()
{
    if (length(g_offset_px) > 0.5 * u_size_px)
        discard; // round dots
    frag_color = u_color;
}
