#version 330 core
// Blinn-Phong with a key light and a fill light fixed to the camera, so the lighting does not
// swing around while the user rotates the model. The diffuse colour is the material's (times its
// texture), a per-vertex colour (curvature), or, unlit, the normal or the texture coordinates.
// Bumps perturb the normal by the height image's screen-space gradient: the surface-gradient
// method of Mikkelsen 2010, "Bump Mapping Unparametrized Surfaces on the GPU" (no tangents).
in vec3 v_position_view;
in vec3 v_normal_view;
in vec2 v_uv;
in vec3 v_color;

uniform vec3 u_color;           // diffuse colour
uniform vec3 u_specular_color;
uniform float u_shininess;
uniform bool u_two_sided;       // light back faces with the flipped normal
uniform vec3 u_key_direction;   // towards the light, view space, unit
uniform vec3 u_key_color;
uniform vec3 u_fill_direction;
uniform vec3 u_fill_color;
uniform vec3 u_ambient_color;
uniform bool u_orthographic;
uniform int u_color_mode;       // 0 material, 1 vertex colour, 2 normals, 3 texture coordinates
uniform bool u_textured;
uniform sampler2D u_texture;
uniform bool u_bumped;
uniform sampler2D u_bump;
uniform float u_bump_height;    // model units of the height image's full range
uniform bool u_highlighted;     // the selected surface: tinted, strongest at the silhouette
uniform vec3 u_highlight_color;

out vec4 frag_color;

vec3 blinn_phong(vec3 n, vec3 v, vec3 l, vec3 light_color, vec3 diffuse_color) {
  float diffuse = max(dot(n, l), 0.0);
  vec3 h = normalize(l + v);
  float specular = diffuse > 0.0 ? pow(max(dot(n, h), 0.0), u_shininess) : 0.0;
  return light_color * (diffuse * diffuse_color + specular * u_specular_color);
}

/// The bumped normal (Mikkelsen 2010, listing 1); a flat height image leaves n as it is.
vec3 bump(vec3 n) {
  float h = u_bump_height * texture(u_bump, v_uv).r;
  float hx = dFdx(h);
  float hy = dFdy(h);
  if (hx == 0.0 && hy == 0.0) return n;
  vec3 dpdx = dFdx(v_position_view);
  vec3 dpdy = dFdy(v_position_view);
  vec3 r1 = cross(dpdy, n);
  vec3 r2 = cross(n, dpdx);
  float det = dot(dpdx, r1);
  vec3 gradient = sign(det) * (hx * r1 + hy * r2);
  return normalize(abs(det) * n - gradient);
}

/// The highlight: a light tint everywhere and the highlight colour towards the silhouette (a
/// rim), so the outline reads at a glance while the shading still shows the shape.
vec3 highlight(vec3 color, vec3 n, vec3 v) {
  if (!u_highlighted) return color;
  float rim = 1.0 - abs(dot(n, v));
  return mix(color, u_highlight_color, 0.18 + 0.72 * rim * rim * rim);
}

void main() {
  vec3 n = normalize(v_normal_view);
  if (u_two_sided && !gl_FrontFacing) n = -n;
  vec3 v = u_orthographic ? vec3(0.0, 0.0, 1.0) : normalize(-v_position_view);
  if (u_color_mode == 2) {
    frag_color = vec4(highlight(0.5 * n + 0.5, n, v), 1.0);
    return;
  }
  if (u_color_mode == 3) {
    frag_color = vec4(highlight(vec3(fract(v_uv), 0.0), n, v), 1.0);
    return;
  }
  vec3 base = u_color_mode == 1 ? v_color : u_color;
  if (u_color_mode == 0 && u_textured) base *= texture(u_texture, v_uv).rgb;
  if (u_color_mode == 0 && u_bumped) n = bump(n);
  vec3 color = u_ambient_color * base;
  color += blinn_phong(n, v, u_key_direction, u_key_color, base);
  color += blinn_phong(n, v, u_fill_direction, u_fill_color, base);
  frag_color = vec4(highlight(clamp(color, 0.0, 1.0), n, v), 1.0);
}
