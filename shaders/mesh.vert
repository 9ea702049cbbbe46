#version 330 core
// Surfaces: positions and per-vertex normals in world space, lit in view space; texture
// coordinates and a per-vertex colour (curvature colours) passed through.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
layout(location = 3) in vec3 a_color;

uniform mat4 u_model;  // identity, or a rider's rigid placement (model/riders.hpp)
uniform mat4 u_view;
uniform mat4 u_projection;

out vec3 v_position_view;
out vec3 v_normal_view;
out vec2 v_uv;
out vec3 v_color;

void main() {
  mat4 model_view = u_view * u_model;
  vec4 position_view = model_view * vec4(a_position, 1.0);
  v_position_view = position_view.xyz;
  // The view and model matrices are rotations plus translations, so they transform normals too.
  v_normal_view = mat3(model_view) * a_normal;
  v_uv = a_uv;
  v_color = a_color;
  gl_Position = u_projection * position_view;
}
