#include "io/mesh/obj_writer.hpp"

#include "geometry/thread_pool.hpp"
#include "io/files/atomic_file.hpp"

#include <algorithm>
#include <atomic>
#include <charconv>
#include <cmath>
#include <condition_variable>
#include <cstring>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace sweep::io {
namespace {

/// Items of a section formatted on one thread at a time: few enough that their text (about
/// 130 KB) is still in the caches when another thread writes it (chunks of 32 768 items made the
/// 2-thread export 8 % slower than these).
constexpr std::size_t kChunkItems = 1 << 11;
/// Room for a chunk's text, made once per slot and not zeroed: its longest lines (faces with
/// 8-digit v/vt/vn indices) take 83 bytes; a longer chunk grows its memory.
constexpr std::size_t kChunkBytes = kChunkItems * 96;

/// A chunk's text, formatted straight into memory kept for the slot's next chunk.
struct ChunkText {
  std::unique_ptr<char[]> data;
  std::size_t capacity = 0;
  std::size_t size = 0;
  std::string_view view() const { return {data.get(), size}; }
};

/// Collects OBJ text for a sink: a file, through a fixed buffer handed to it when full, or a
/// chunk's text formatted on another thread, in memory that grows as needed. No per-line
/// allocation, and a chunk's text is not copied before it goes to the file.
class ObjBuffer {
 public:
  explicit ObjBuffer(std::FILE* out) : out_(out), buf_(own_), capacity_(sizeof own_) {}
  /// Formats into `text` from its start; flush() sets its size.
  explicit ObjBuffer(ChunkText* text) : text_(text) {
    if (text->capacity == 0) {
      text->data.reset(new char[kChunkBytes]);
      text->capacity = kChunkBytes;
    }
    buf_ = text->data.get();
    capacity_ = text->capacity;
  }

  void text(std::string_view s) {
    if (!text_ && s.size() > capacity_ / 2) return block(s);  // a long comment or name, at once
    reserve(s.size());
    std::memcpy(buf_ + used_, s.data(), s.size());
    used_ += s.size();
  }
  /// Room for `n` bytes written through the pointer; advance() past what was written.
  char* room(std::size_t n) {
    reserve(n);
    return buf_ + used_;
  }
  void advance(const char* end) { used_ = static_cast<std::size_t>(end - buf_); }
  void number(float v) {
    reserve(32);
    used_ = static_cast<std::size_t>(std::to_chars(buf_ + used_, buf_ + capacity_, v).ptr - buf_);
  }
  void number(std::uint32_t v) {
    reserve(16);
    used_ = static_cast<std::size_t>(std::to_chars(buf_ + used_, buf_ + capacity_, v).ptr - buf_);
  }
  void ch(char c) {
    reserve(1);
    buf_[used_++] = c;
  }
  bool flush() {
    if (text_) {
      text_->size = used_;
      return true;
    }
    if (used_ > 0 && ok_) ok_ = std::fwrite(buf_, 1, used_, out_) == used_;
    used_ = 0;
    return ok_;
  }
  /// Text of any length to the file, after what is buffered (a chunk formatted on another thread).
  void block(std::string_view s) {
    flush();
    if (!s.empty() && ok_) ok_ = std::fwrite(s.data(), 1, s.size(), out_) == s.size();
  }

 private:
  void reserve(std::size_t n) {
    if (used_ + n <= capacity_) return;
    if (!text_) {
      flush();
      return;
    }
    const std::size_t capacity = std::max(used_ + n, 2 * capacity_);
    std::unique_ptr<char[]> bigger(new char[capacity]);
    std::copy(buf_, buf_ + used_, bigger.get());
    text_->data = std::move(bigger);
    text_->capacity = capacity_ = capacity;
    buf_ = text_->data.get();
  }
  std::FILE* out_ = nullptr;
  ChunkText* text_ = nullptr;
  char own_[1 << 16];
  char* buf_ = nullptr;
  std::size_t capacity_ = 0;
  std::size_t used_ = 0;
  bool ok_ = true;
};

/// Chunks of one section formatted on several threads and written in order as they come, by
/// whichever thread finishes the next one to write (outside the lock, so the others go on
/// formatting meanwhile): writing the file overlaps formatting. A chunk waits to start until it
/// is fewer than `slots` ahead of the next one to write, so at most `slots` texts are kept.
class ChunkPipeline {
 public:
  ChunkPipeline(ObjBuffer& out, std::size_t slots) : out_(out), texts_(slots), ready_(slots, false) {}

  /// Waits until chunk `i` may be formatted; returns its text to fill, or nullptr after a failure.
  ChunkText* start(std::size_t i) {
    std::unique_lock<std::mutex> lock(mutex_);
    moved_.wait(lock, [&] { return failed_ || i < written_ + texts_.size(); });
    return failed_ ? nullptr : &texts_[i % texts_.size()];
  }

  /// Chunk `i` is formatted: writes it and the ready ones after it, unless another thread is.
  void finish(std::size_t i) {
    std::unique_lock<std::mutex> lock(mutex_);
    ready_[i % texts_.size()] = true;
    if (writing_) return;
    writing_ = true;
    for (std::size_t slot = written_ % texts_.size(); ready_[slot]; slot = written_ % texts_.size()) {
      lock.unlock();
      out_.block(texts_[slot].view());
      lock.lock();
      ready_[slot] = false;
      ++written_;
      moved_.notify_all();
    }
    writing_ = false;
  }

  /// A chunk failed: the threads waiting to start stop waiting.
  void fail() {
    const std::lock_guard<std::mutex> lock(mutex_);
    failed_ = true;
    moved_.notify_all();
  }

 private:
  ObjBuffer& out_;
  std::vector<ChunkText> texts_;  // chunk i's in texts_[i % size]
  std::vector<bool> ready_;
  std::size_t written_ = 0;  // chunks written, in order
  bool writing_ = false;
  bool failed_ = false;
  std::mutex mutex_;
  std::condition_variable moved_;
};

/// Writes the lines of items [0, count) through `format(buffer, begin, end)`: on one thread into
/// `b`, or, with more threads and more than one chunk, in chunks formatted in parallel and written
/// in order (ChunkPipeline), so the bytes are the same whatever the thread count.
template <typename Format>
void write_section(ObjBuffer& b, std::size_t count, int threads, const Format& format) {
  if (threads <= 1 || count <= kChunkItems) {
    format(b, 0, count);
    return;
  }
  ChunkPipeline pipeline(b, 2 * static_cast<std::size_t>(threads));
  parallel_chunks(count, kChunkItems, threads, [&](std::size_t begin, std::size_t end, int) {
    const std::size_t i = begin / kChunkItems;
    try {
      ChunkText* text = pipeline.start(i);
      if (!text) return;
      ObjBuffer chunk(text);
      format(chunk, begin, end);
      chunk.flush();
      pipeline.finish(i);
    } catch (...) {
      pipeline.fail();
      throw;
    }
  });
}

void write_vectors(ObjBuffer& b, std::string_view tag, const std::vector<glm::vec3>& vs, int threads) {
  write_section(b, vs.size(), threads, [&](ObjBuffer& out, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      out.text(tag);
      out.number(vs[i].x);
      out.ch(' ');
      out.number(vs[i].y);
      out.ch(' ');
      out.number(vs[i].z);
      out.ch('\n');
    }
  });
}

void write_uvs(ObjBuffer& b, const std::vector<glm::vec2>& uvs, int threads) {
  write_section(b, uvs.size(), threads, [&](ObjBuffer& out, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      out.text("vt ");
      out.number(uvs[i].x);
      out.ch(' ');
      out.number(uvs[i].y);
      out.ch('\n');
    }
  });
}

/// One corner's index, formatted once for its two or three uses, with the fixed-size copies the
/// compiler makes moves rather than calls (a call to memmove per number was 17 % of an export).
struct IndexText {
  explicit IndexText(std::uint32_t index)
      : size(static_cast<std::size_t>(std::to_chars(digits, digits + sizeof digits, index).ptr - digits)) {}
  char* put(char* at) const {
    std::memcpy(at, digits, sizeof digits);
    return at + size;
  }
  char digits[16] = {};
  std::size_t size;
};

/// One face's corners [corner, corner + size): " v//vn" each, or " v/vt/vn" with texture
/// coordinates (position, texture coordinate and normal share their index).
void write_face(ObjBuffer& out, const std::vector<std::uint32_t>& indices, std::size_t corner, std::size_t size,
                bool uvs) {
  out.ch('f');
  for (std::size_t k = 0; k < size && corner + k < indices.size(); ++k) {
    const IndexText number(indices[corner + k] + 1);  // OBJ counts from 1
    char* at = out.room(64);                          // " " 3 numbers "//": 26 bytes, each copy 16
    *at++ = ' ';
    at = number.put(at);
    *at++ = '/';
    if (uvs) at = number.put(at);
    *at++ = '/';
    at = number.put(at);
    out.advance(at);
  }
  out.ch('\n');
}

/// A polygon mesh keeps its polygons (written on one thread: their corners are a running sum);
/// otherwise every triangle is a face.
void write_faces(ObjBuffer& b, const Mesh& mesh, bool uvs, int threads) {
  if (!mesh.polygon_sizes.empty()) {
    std::size_t corner = 0;
    for (const std::uint32_t size : mesh.polygon_sizes) {
      write_face(b, mesh.polygon_indices, corner, size, uvs);
      corner += size;
    }
    return;
  }
  write_section(b, mesh.indices.size() / 3, threads, [&](ObjBuffer& out, std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f < end; ++f) write_face(out, mesh.indices, 3 * f, 3, uvs);
  });
}

}  // namespace

bool has_texture_coordinates(const Mesh& mesh) {
  return !mesh.uvs.empty() && mesh.uvs.size() == mesh.positions.size();
}

bool write_obj(std::FILE* out, const Mesh& mesh, const std::string& comment, const ObjMaterialLink& material) {
  ObjBuffer b(out);
  if (!comment.empty()) {
    b.text("# ");
    b.text(comment);
    b.ch('\n');
  }
  if (!material.library.empty()) {
    b.text("mtllib ");
    b.text(material.library);
    b.ch('\n');
  }
  const int threads = worker_count();
  write_vectors(b, "v ", mesh.positions, threads);
  const bool uvs = has_texture_coordinates(mesh);
  if (uvs) write_uvs(b, mesh.uvs, threads);
  write_vectors(b, "vn ", mesh.normals, threads);
  if (!material.material.empty()) {
    b.text("usemtl ");
    b.text(material.material);
    b.ch('\n');
  }
  write_faces(b, mesh, uvs, threads);
  return b.flush();
}

std::string obj_text(const Mesh& mesh, const std::string& comment, const ObjMaterialLink& material) {
  char* data = nullptr;
  std::size_t size = 0;
  std::FILE* memory = ::open_memstream(&data, &size);
  if (!memory) throw std::runtime_error("cannot allocate OBJ text");
  write_obj(memory, mesh, comment, material);
  std::fclose(memory);
  std::string text(data, size);
  std::free(data);
  return text;
}

namespace {

/// Whether every element of `values` is finite, the elements checked in parts on the worker
/// threads (a large mesh's 20 MB are read twice per export: before anything is written, and by
/// the writer's own check).
template <typename Vec>
bool all_finite(const std::vector<Vec>& values) {
  constexpr std::size_t kPart = 1 << 16;
  std::atomic<bool> finite{true};
  parallel_chunks(values.size(), kPart, values.size() < 2 * kPart ? 1 : worker_count(),
                  [&](std::size_t begin, std::size_t end, int) {
                    for (std::size_t i = begin; i < end && finite.load(std::memory_order_relaxed); ++i) {
                      for (int k = 0; k < Vec::length(); ++k) {
                        if (!std::isfinite(values[i][k])) finite = false;
                      }
                    }
                  });
  return finite;
}

}  // namespace

bool mesh_is_finite(const Mesh& mesh) {
  return all_finite(mesh.positions) && all_finite(mesh.normals) && all_finite(mesh.uvs);
}

void save_obj_file(const std::filesystem::path& path, const Mesh& mesh, const std::string& comment,
                   const ObjMaterialLink& material) {
  if (!mesh_is_finite(mesh)) {
    throw std::runtime_error("cannot write " + path.string() + ": the mesh has a NaN or infinite coordinate");
  }
  write_file_atomically(path, [&](std::FILE* f) { return write_obj(f, mesh, comment, material); });
}

}  // namespace sweep::io
