#version 330 core
// Wireframe (wire.geom): a fragment within half a line's width of its triangle's nearest edge
// takes the flat wire colour, its coverage fading over the last pixel (alpha to coverage smooths
// the lines under multisampling); the rest of the triangle is discarded, so the edges behind
// show through as with lines.
noperspective in vec3 g_edge_distance;

uniform vec3 u_color;
uniform float u_half_width;  // pixels

out vec4 frag_color;

void main() {
  float d = min(g_edge_distance.x, min(g_edge_distance.y, g_edge_distance.z));
  float coverage = 1.0 - smoothstep(u_half_width - 0.5, u_half_width + 0.5, d);
  if (coverage <= 0.0) discard;
  frag_color = vec4(u_color, coverage);
}
