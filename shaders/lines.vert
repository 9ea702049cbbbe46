#version 330 core
// Curves, frames, normal segments and control points. A vertex sits at a_position plus
// a_direction scaled by u_direction_length, so frame axes and normals get a length in
// proportion to the scene without re-uploading anything when the scene's size changes.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_direction;
layout(location = 2) in vec3 a_color;

uniform mat4 u_view;
uniform mat4 u_projection;
uniform float u_direction_length;
uniform float u_point_size;

out vec3 v_color;

void main() {
  v_color = a_color;
  gl_PointSize = u_point_size;
  gl_Position = u_projection * u_view * vec4(a_position + u_direction_length * a_direction, 1.0);
}
