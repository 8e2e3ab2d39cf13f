// The pass-floor microbenchmark's full-screen triangle (src/eval/pass_floor.h).
void main() {
  vec2 q = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
  gl_Position = vec4(q * 2.0 - 1.0, 0.0, 1.0);
}
