#version 330 core
flat in uint g_face;
flat in ivec3 g_vertices;
flat in vec2 g_window[3];

out uvec2 ids; // face + 1, vertex + 1; 0 is the background

void main()
{
    int nearest = 0;
    float best = distance(gl_FragCoord.xy, g_window[0]);
    for (int k = 1; k < 3; ++k)
    {
        float d = distance(gl_FragCoord.xy, g_window[k]);
        if (d < best)
        {
            best = d;
            nearest = k;
        }
    }
    ids = uvec2(g_face + 1u, uint(g_vertices[nearest]) + 1u);
}
