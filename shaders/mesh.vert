#version 330 core
// Surfaces: positions and per-vertex normals in world space, lit in view space.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;

uniform mat4 u_view;
uniform mat4 u_projection;

out vec3 v_position_view;
out vec3 v_normal_view;

void main() {
  vec4 position_view = u_view * vec4(a_position, 1.0);
  v_position_view = position_view.xyz;
  // The view matrix is a rotation plus a translation, so it transforms normals as well.
  v_normal_view = mat3(u_view) * a_normal;
  gl_Position = u_projection * position_view;
}
