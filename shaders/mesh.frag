#version 330 core
// Headlight shading, lit on both sides. Flat shading takes the polygon's own normal (its
// area vector, fetched through the triangle's face), so a fan-triangulated quad is shaded
// as one polygon; back faces are tinted so that holes and flipped faces show.
in vec3 v_position_view;
in vec3 v_normal_view;
in vec3 v_color;
in float v_selected;

uniform mat4 u_view;
uniform bool u_flat;
uniform bool u_back_tint;
uniform bool u_orthographic;
uniform usamplerBuffer u_triangle_face;
uniform samplerBuffer u_face_area;
uniform usamplerBuffer u_face_selected;
uniform vec3 u_selection_color;
uniform vec3 u_back_face_color;

out vec4 frag_color;

void main()
{
    int f = int(texelFetch(u_triangle_face, gl_PrimitiveID).r);
    vec3 n = u_flat ? mat3(u_view) * texelFetch(u_face_area, f).xyz : v_normal_view;
    float len = length(n);
    n = len > 0.0 ? n / len : vec3(0.0, 0.0, 1.0);
    vec3 to_eye = u_orthographic ? vec3(0.0, 0.0, 1.0) : normalize(-v_position_view);
    if (dot(n, to_eye) < 0.0)
        n = -n;
    vec3 base = v_color;
    if (!gl_FrontFacing && u_back_tint)
        base = mix(base, u_back_face_color, 0.65);
    if (texelFetch(u_face_selected, f).r != 0u)
        base = mix(base, u_selection_color, 0.55); // a selected face
    else
        // Selected vertices tint the surface around them, which stays shaded and readable
        // however dense the mesh.
        base = mix(base, u_selection_color, 0.55 * v_selected);
    float diffuse = max(dot(n, to_eye), 0.0);
    float specular = pow(diffuse, 48.0);
    frag_color = vec4(base * (0.20 + 0.80 * diffuse) + vec3(0.16) * specular, 1.0);
}
