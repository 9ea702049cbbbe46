#version 330 core
in vec3 v_color;

uniform bool u_round_points;  // control points: discs rather than squares
uniform vec3 u_tint;          // multiplies the vertex colour

out vec4 frag_color;

void main() {
  if (u_round_points && length(gl_PointCoord - vec2(0.5)) > 0.5) discard;
  frag_color = vec4(u_tint * v_color, 1.0);
}
