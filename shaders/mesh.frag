#version 330 core
// Headlight shading, lit on both sides. Flat shading takes the polygon's own normal (its
// area vector, fetched through the triangle's face), so a fan-triangulated quad is shaded
// as one polygon; back faces are tinted so that holes and flipped faces show.
in vec3 v_position_view;
in vec3 v_normal_view;
in vec3 v_color;

uniform mat4 u_view;
uniform bool u_flat;
uniform bool u_back_tint;
uniform bool u_orthographic;
uniform usamplerBuffer u_triangle_face;
uniform samplerBuffer u_face_area;

out vec4 frag_color;

void main()
{
    vec3 n = v_normal_view;
    if (u_flat)
    {
        int f = int(texelFetch(u_triangle_face, gl_PrimitiveID).r);
        n = mat3(u_view) * texelFetch(u_face_area, f).xyz;
    }
    float len = length(n);
    n = len > 0.0 ? n / len : vec3(0.0, 0.0, 1.0);
    vec3 to_eye = u_orthographic ? vec3(0.0, 0.0, 1.0) : normalize(-v_position_view);
    if (dot(n, to_eye) < 0.0)
        n = -n;
    vec3 base = v_color;
    if (!gl_FrontFacing && u_back_tint)
        base = mix(base, vec3(0.22, 0.36, 0.80), 0.65);
    float diffuse = max(dot(n, to_eye), 0.0);
    float specular = pow(diffuse, 48.0);
    frag_color = vec4(base * (0.20 + 0.80 * diffuse) + vec3(0.16) * specular, 1.0);
}
