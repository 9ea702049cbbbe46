#version 330 core
// Wireframe without line rasterization: each triangle passes through whole, and each of its
// corners gets its distance in pixels to the opposite edge (the triangle's heights), so that
// wire.frag knows, interpolated without perspective, how far a fragment is from the nearest edge
// (Bærentzen et al., "Single-pass wireframe rendering", SIGGRAPH 2006 sketches).
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

uniform vec2 u_viewport;  // the target's size in pixels

noperspective out vec3 g_edge_distance;

vec2 pixels(int k) {
  // A corner behind the eye would flip sign; w is kept positive (such triangles are clipped anyway).
  return 0.5 * u_viewport * gl_in[k].gl_Position.xy / max(gl_in[k].gl_Position.w, 1e-6);
}

void main() {
  vec2 p0 = pixels(0);
  vec2 p1 = pixels(1);
  vec2 p2 = pixels(2);
  vec2 e0 = p2 - p1;
  vec2 e1 = p2 - p0;
  vec2 e2 = p1 - p0;
  float twice_area = abs(e1.x * e2.y - e1.y * e2.x);
  vec3 heights = twice_area / max(vec3(length(e0), length(e1), length(e2)), vec3(1e-6));
  gl_Position = gl_in[0].gl_Position;
  g_edge_distance = vec3(heights.x, 0.0, 0.0);
  EmitVertex();
  gl_Position = gl_in[1].gl_Position;
  g_edge_distance = vec3(0.0, heights.y, 0.0);
  EmitVertex();
  gl_Position = gl_in[2].gl_Position;
  g_edge_distance = vec3(0.0, 0.0, heights.z);
  EmitVertex();
  EndPrimitive();
}
