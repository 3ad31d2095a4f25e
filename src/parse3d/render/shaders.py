"""GLSL sources of the renderer (OpenGL 3.3 core).

Three programs share one vertex layout (``in_pos``, ``in_normal`` in the mesh's own frame,
``in_color`` linear RGB, ``in_mat`` = roughness and metallic, ``in_part`` the part's local
index within its mesh):

* ``SHADOW`` writes light-space depth only (the key light's shadow map);
* ``COLOR`` shades with a hemisphere ambient, a shadowed key light and an unshadowed fill
  light, then tone-maps and encodes sRGB;
* ``IDS`` writes exact per-pixel ids, camera-frame depth and world normals into float32
  attachments (no multisampling, so every value comes from the one triangle covering the
  pixel centre);
* ``MASK`` writes the instance id alone (the first channel of the ids attachment).
"""

from __future__ import annotations

SHADOW_VS = """
#version 330
uniform mat4 u_light_vp;
uniform mat4 u_model;
in vec3 in_pos;
void main() {
    gl_Position = u_light_vp * u_model * vec4(in_pos, 1.0);
}
"""

SHADOW_FS = """
#version 330
void main() {}
"""

COLOR_VS = """
#version 330
uniform mat4 u_model;
uniform mat3 u_normal_mat;
uniform mat4 u_view_proj;
in vec3 in_pos;
in vec3 in_normal;
in vec3 in_color;
in vec2 in_mat;
out vec3 v_world;
out vec3 v_normal;
out vec3 v_color;
out vec2 v_mat;
void main() {
    vec4 w = u_model * vec4(in_pos, 1.0);
    v_world = w.xyz;
    v_normal = u_normal_mat * in_normal;
    v_color = in_color;
    v_mat = in_mat;
    gl_Position = u_view_proj * w;
}
"""

COLOR_FS = """
#version 330
const float PI = 3.14159265;
uniform vec3 u_eye;
uniform bool u_ortho;
uniform vec3 u_view_dir;
uniform vec3 u_light_dir;
uniform vec3 u_light_color;
uniform vec3 u_fill_dir;
uniform vec3 u_fill_color;
uniform vec3 u_sky;
uniform vec3 u_ground;
uniform float u_exposure;
uniform mat4 u_light_vp;
uniform float u_shadow_offset;
uniform float u_shadow_texel;
uniform bool u_shadows;
uniform sampler2DShadow u_shadow;
in vec3 v_world;
in vec3 v_normal;
in vec3 v_color;
in vec2 v_mat;
out vec4 f_color;

float shadow_factor(vec3 n, float ndl) {
    if (!u_shadows) return 1.0;
    // normal-offset shadow lookup: move the lookup point off the surface by a few texels
    vec3 p = v_world + n * u_shadow_offset * (1.5 - ndl);
    vec4 q = u_light_vp * vec4(p, 1.0);
    vec3 s = q.xyz / q.w * 0.5 + 0.5;
    if (s.x < 0.0 || s.x > 1.0 || s.y < 0.0 || s.y > 1.0 || s.z > 1.0) return 1.0;
    // four bilinear (hardware 2x2 PCF) taps: a soft 4x4-texel footprint
    float d = 0.75 * u_shadow_texel;
    float ref = s.z - 0.0005;
    float sum = texture(u_shadow, vec3(s.xy + vec2(-d, -d), ref))
              + texture(u_shadow, vec3(s.xy + vec2(d, -d), ref))
              + texture(u_shadow, vec3(s.xy + vec2(-d, d), ref))
              + texture(u_shadow, vec3(s.xy + vec2(d, d), ref));
    return sum * 0.25;
}

vec3 aces(vec3 x) {
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

void main() {
    vec3 n = normalize(v_normal);
    if (!gl_FrontFacing) n = -n;
    vec3 v = u_ortho ? -u_view_dir : normalize(u_eye - v_world);
    vec3 albedo = v_color;
    float rough = clamp(v_mat.x, 0.08, 1.0);
    float metal = clamp(v_mat.y, 0.0, 1.0);
    vec3 f0 = mix(vec3(0.04), albedo, metal);
    vec3 diffuse = albedo * (1.0 - metal);

    float shininess = clamp(2.0 / pow(rough, 4.0) - 2.0, 1.0, 2048.0);
    vec3 l = normalize(u_light_dir);
    float ndl = max(dot(n, l), 0.0);
    vec3 h = normalize(l + v);
    float ndh = max(dot(n, h), 0.0);
    vec3 fresnel = f0 + (1.0 - f0) * pow(1.0 - max(dot(h, v), 0.0), 5.0);
    float norm = (shininess + 8.0) / (8.0 * PI);
    vec3 spec = fresnel * norm * pow(ndh, shininess) * 0.25;
    float sh = shadow_factor(n, ndl);
    vec3 key = u_light_color * ndl * sh * (diffuse + spec);

    vec3 fl = normalize(u_fill_dir);
    vec3 fill = u_fill_color * max(dot(n, fl), 0.0) * diffuse;

    vec3 hemi = mix(u_ground, u_sky, 0.5 + 0.5 * n.z);
    vec3 ambient = hemi * (diffuse + f0 * 0.5);

    vec3 c = (key + fill + ambient) * u_exposure;
    c = aces(c);
    f_color = vec4(pow(c, vec3(1.0 / 2.2)), 1.0);
}
"""

IDS_VS = """
#version 330
uniform mat4 u_model;
uniform mat3 u_normal_mat;
uniform mat4 u_view;
uniform mat4 u_proj;
in vec3 in_pos;
in vec3 in_normal;
in float in_part;
out vec3 v_eye;
out vec3 v_normal;
flat out float v_part;
void main() {
    vec4 e = u_view * (u_model * vec4(in_pos, 1.0));
    v_eye = e.xyz;
    v_normal = u_normal_mat * in_normal;
    v_part = in_part;
    gl_Position = u_proj * e;
}
"""

IDS_FS = """
#version 330
uniform float u_instance;
uniform float u_part_base;
in vec3 v_eye;
in vec3 v_normal;
flat in float v_part;
layout(location = 0) out vec4 f_ids;
layout(location = 1) out vec4 f_normal;
void main() {
    vec3 n = normalize(v_normal);
    if (!gl_FrontFacing) n = -n;
    // camera-frame depth (OpenCV +z) is minus the OpenGL eye z
    f_ids = vec4(u_instance, u_part_base + v_part, -v_eye.z, 1.0);
    f_normal = vec4(n, 1.0);
}
"""

# instance ids only (choosing a viewpoint among candidates): the position computed as in
# IDS_VS, so coverage and depth tests, hence the ids, are the same
MASK_VS = """
#version 330
uniform mat4 u_model;
uniform mat4 u_view;
uniform mat4 u_proj;
in vec3 in_pos;
void main() {
    vec4 e = u_view * (u_model * vec4(in_pos, 1.0));
    gl_Position = u_proj * e;
}
"""

MASK_FS = """
#version 330
uniform float u_instance;
layout(location = 0) out vec4 f_ids;
void main() {
    f_ids = vec4(u_instance, 0.0, 0.0, 1.0);
}
"""
