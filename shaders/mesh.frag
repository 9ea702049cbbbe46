#version 330 core
// Blinn-Phong with a key light and a fill light fixed to the camera, so the lighting does not
// swing around while the user rotates the model.
in vec3 v_position_view;
in vec3 v_normal_view;

uniform vec3 u_color;           // diffuse colour
uniform vec3 u_specular_color;
uniform float u_shininess;
uniform bool u_two_sided;       // light back faces with the flipped normal
uniform bool u_unlit;           // wireframe: flat u_color
uniform vec3 u_key_direction;   // towards the light, view space, unit
uniform vec3 u_key_color;
uniform vec3 u_fill_direction;
uniform vec3 u_fill_color;
uniform vec3 u_ambient_color;
uniform bool u_orthographic;

out vec4 frag_color;

vec3 blinn_phong(vec3 n, vec3 v, vec3 l, vec3 light_color) {
  float diffuse = max(dot(n, l), 0.0);
  vec3 h = normalize(l + v);
  float specular = diffuse > 0.0 ? pow(max(dot(n, h), 0.0), u_shininess) : 0.0;
  return light_color * (diffuse * u_color + specular * u_specular_color);
}

void main() {
  if (u_unlit) {
    frag_color = vec4(u_color, 1.0);
    return;
  }
  vec3 n = normalize(v_normal_view);
  if (u_two_sided && !gl_FrontFacing) n = -n;
  vec3 v = u_orthographic ? vec3(0.0, 0.0, 1.0) : normalize(-v_position_view);
  vec3 color = u_ambient_color * u_color;
  color += blinn_phong(n, v, u_key_direction, u_key_color);
  color += blinn_phong(n, v, u_fill_direction, u_fill_color);
  frag_color = vec4(clamp(color, 0.0, 1.0), 1.0);
}
