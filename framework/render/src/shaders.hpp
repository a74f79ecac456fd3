// GLSL 3.30 core sources of the renderer's programs (internal header).
#pragma once

namespace jelly::render::shaders {

// Lit surfaces: terrains and the bodies' surfaces. Double-sided: the normal is turned
// towards the viewer, or, for a two-toned sheet (u_two_tone), flipped on back faces, which get
// their own tint.
inline constexpr const char* kSurfaceVertex = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
uniform mat4 u_view_projection;
out vec3 v_world;
out vec3 v_normal;
void main() {
  v_world = a_position;
  v_normal = a_normal;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
)";

inline constexpr const char* kSurfaceFragment = R"(#version 330 core
in vec3 v_world;
in vec3 v_normal;
uniform vec3 u_color;
uniform vec3 u_eye;
uniform float u_specular;      // strength of the key light's highlight
uniform float u_shininess;
uniform int u_plane;           // 1: planes (grid, hole, fade to the sky)
uniform int u_grid;
uniform vec3 u_axis_u;         // plane basis for the grid [unit]
uniform vec3 u_axis_w;
uniform vec3 u_plane_normal;
uniform int u_has_hole;
uniform vec3 u_hole_center;    // [m]
uniform float u_hole_radius;   // [m], the physical radius: fragments inside are discarded
uniform vec3 u_fade_center;    // the plane fades into the sky towards its drawn edge
uniform float u_fade_radius;
uniform vec3 u_sky;
uniform vec2 u_cavity;         // bowl: (bottom y, rim y); deeper is darker (fake occlusion)
uniform int u_two_tone;        // 1: a sheet, front (u_color) and back (u_back_color) differ
uniform vec3 u_back_color;
out vec4 frag_color;

float grid_line(vec2 g) {
  vec2 w = fwidth(g);
  vec2 d = abs(fract(g - 0.5) - 0.5) / max(w, vec2(1e-6));
  return 1.0 - min(min(d.x, d.y), 1.0);
}

void main() {
  vec3 base = u_color;
  if (u_plane == 1) {
    if (u_has_hole == 1) {
      vec3 r = v_world - u_hole_center;
      r -= dot(r, u_plane_normal) * u_plane_normal;
      float d = length(r);
      if (d < u_hole_radius) discard;
      base *= mix(0.55, 1.0, smoothstep(0.0, 0.08, d - u_hole_radius));  // a dark lip at the edge
    }
    if (u_grid == 1) {
      vec2 g = vec2(dot(v_world, u_axis_u), dot(v_world, u_axis_w));
      float minor = grid_line(g);
      float major = grid_line(g / 5.0);
      base *= 1.0 - 0.22 * minor - 0.30 * major;
    }
  }
  if (u_cavity.y > u_cavity.x) {
    float depth = clamp((u_cavity.y - v_world.y) / (u_cavity.y - u_cavity.x), 0.0, 1.0);
    base *= mix(1.0, 0.45, depth * depth);
  }
  vec3 n = normalize(v_normal);
  vec3 v = normalize(u_eye - v_world);
  if (u_two_tone == 1) {
    // A sheet: the back faces (by winding) take the flipped normal and their own tint.
    if (!gl_FrontFacing) {
      n = -n;
      base = u_back_color;
    }
  } else if (dot(n, v) < 0.0) {
    n = -n;
  }
  vec3 key = normalize(vec3(0.45, 0.85, 0.35));
  vec3 fill = normalize(vec3(-0.6, 0.35, -0.55));
  float hemi = 0.5 + 0.5 * n.y;
  vec3 ambient = mix(vec3(0.20, 0.19, 0.18), vec3(0.36, 0.39, 0.45), hemi);
  vec3 c = base * (ambient + 0.78 * max(dot(n, key), 0.0) + 0.22 * max(dot(n, fill), 0.0));
  if (u_two_tone == 1) c += base * 0.45 * max(-n.y, 0.0);  // light bounced up onto a sheet's underside
  vec3 h = normalize(key + v);
  c += u_specular * pow(max(dot(n, h), 0.0), u_shininess) * vec3(1.0);
  float rim = pow(1.0 - max(dot(n, v), 0.0), 3.0);
  c += 0.10 * rim * u_specular * vec3(1.0);
  if (u_plane == 1) {
    vec3 r = v_world - u_fade_center;
    float d = length(r - dot(r, u_plane_normal) * u_plane_normal);
    c = mix(c, u_sky, smoothstep(0.55 * u_fade_radius, u_fade_radius, d));
  }
  frag_color = vec4(pow(c, vec3(1.0 / 1.1)), 1.0);
}
)";

// Particles (round dots) and springs (lines): one colour per draw.
inline constexpr const char* kFlatVertex = R"(#version 330 core
layout(location = 0) in vec3 a_position;
uniform mat4 u_view_projection;
uniform float u_point_size;
void main() {
  gl_Position = u_view_projection * vec4(a_position, 1.0);
  gl_PointSize = u_point_size;
}
)";

inline constexpr const char* kFlatFragment = R"(#version 330 core
uniform vec4 u_color;
uniform int u_round;
out vec4 frag_color;
void main() {
  if (u_round == 1 && length(gl_PointCoord - vec2(0.5)) > 0.5) discard;
  frag_color = u_color;
}
)";

// Sky: one full-screen triangle, a vertical gradient.
inline constexpr const char* kSkyVertex = R"(#version 330 core
out float v_height;
void main() {
  vec2 p = vec2((gl_VertexID == 1) ? 3.0 : -1.0, (gl_VertexID == 2) ? 3.0 : -1.0);
  v_height = 0.5 * (p.y + 1.0);
  gl_Position = vec4(p, 0.0, 1.0);
}
)";

inline constexpr const char* kSkyFragment = R"(#version 330 core
in float v_height;
uniform vec3 u_top;
uniform vec3 u_horizon;
out vec4 frag_color;
void main() { frag_color = vec4(mix(u_horizon, u_top, smoothstep(0.0, 1.0, v_height)), 1.0); }
)";

// Overlay: text and rectangles in pixels (top-left origin), colour per vertex.
inline constexpr const char* kOverlayVertex = R"(#version 330 core
layout(location = 0) in vec2 a_pixel;
layout(location = 1) in vec4 a_color;
uniform vec2 u_frame;
out vec4 v_color;
void main() {
  v_color = a_color;
  gl_Position = vec4(2.0 * a_pixel.x / u_frame.x - 1.0, 1.0 - 2.0 * a_pixel.y / u_frame.y, 0.0, 1.0);
}
)";

inline constexpr const char* kOverlayFragment = R"(#version 330 core
in vec4 v_color;
out vec4 frag_color;
void main() { frag_color = v_color; }
)";

}  // namespace jelly::render::shaders
