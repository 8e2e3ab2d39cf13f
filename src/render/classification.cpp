#include "render/classification.h"

#include "gl/timer.h"
#include "shared/bindings.h"

namespace ssr {

void TileClassifier::load(const gl::ShaderSource& src) {
  program_ = gl::Program::compute(src, "render/classify.comp");
  tracer_program_ = gl::Program::compute(src, "render/classify.comp", {"CLASSIFY_FOR_TRACER"});
  tracer_debug_program_ = gl::Program::compute(src, "render/classify.comp", {"CLASSIFY_FOR_TRACER", "SSR_DEBUG_IMAGE"});
}

glm::ivec2 TileClassifier::trace_size(int w, int h, int divisor) {
  return {(w + divisor - 1) / divisor, (h + divisor - 1) / divisor};
}

void TileClassifier::classify(const gl::Texture2D& classes, shared::ClassifyParams p, int frame_index,
                              gl::PassTimer* timer) {
  gl::ScopedPass pass(timer, "classify");
  const glm::ivec2 size = trace_size(classes.width(), classes.height(), p.divisor);
  const glm::ivec2 offset = shared::trace_offset(p.divisor, frame_index);
  p.trace_size = {size, offset};
  prepare(size, p);
  glBindImageTexture(IMG_OUT, classes.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R8);
  program_.dispatch_2d(size.x, size.y);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

void TileClassifier::classify_for_tracer(int width, int height, shared::ClassifyParams p, bool debug,
                                         gl::PassTimer* timer) {
  gl::ScopedPass pass(timer, "classify");
  p.divisor = 1;
  p.trace_size = {width, height, 0, 0};
  p.list_rays = 1;  // the trace runs over the ray list
  prepare({width, height}, p);
  (debug ? tracer_debug_program_ : tracer_program_).dispatch_2d(width, height);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                  GL_TEXTURE_FETCH_BARRIER_BIT);
}

void TileClassifier::prepare(glm::ivec2 size, const shared::ClassifyParams& p) {
  // A list: its header (the indirect dispatch's arguments), then one packed word per entry.
  auto ensure = [](gl::Buffer& list, std::size_t& capacity, std::size_t entries, const char* label) {
    if (list && entries <= capacity) return;
    static_assert(sizeof(shared::TileListHeader) == sizeof(shared::RayListHeader));
    list = gl::make_buffer(label, static_cast<GLsizeiptr>(sizeof(shared::TileListHeader) + entries * sizeof(std::uint32_t)));
    capacity = entries;
  };
  const glm::ivec2 tiles = (size + CLASSIFY_TILE - 1) / CLASSIFY_TILE;
  ensure(tiles_, tiles_capacity_, static_cast<std::size_t>(tiles.x) * static_cast<std::size_t>(tiles.y),
         "classification tiles");
  ensure(rays_, rays_capacity_, static_cast<std::size_t>(size.x) * static_cast<std::size_t>(size.y),
         "classification rays");
  if (!params_) params_ = gl::make_buffer("classification params", sizeof(shared::ClassifyParams));
  glNamedBufferSubData(params_.id(), 0, sizeof(p), &p);
  const shared::TileListHeader no_tiles{0, 1, 1, 0};
  glNamedBufferSubData(tiles_.id(), 0, sizeof(no_tiles), &no_tiles);
  const shared::RayListHeader no_rays{0, 1, 1, 0};
  glNamedBufferSubData(rays_.id(), 0, sizeof(no_rays), &no_rays);
  glBindBufferBase(GL_UNIFORM_BUFFER, UBO_PASS, params_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SSBO_TILES, tiles_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SSBO_RAYS, rays_.id());
}

void TileClassifier::bind() const {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SSBO_TILES, tiles_.id());
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, tiles_.id());
}

void TileClassifier::dispatch() const {
  bind();
  glDispatchComputeIndirect(0);
}

void TileClassifier::dispatch_rays() const {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SSBO_RAYS, rays_.id());
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, rays_.id());
  glDispatchComputeIndirect(0);
}

shared::TileListHeader TileClassifier::read_header() const {
  shared::TileListHeader h{};
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(tiles_.id(), 0, sizeof(h), &h);
  return h;
}

}  // namespace ssr
